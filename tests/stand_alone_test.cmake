# Script mode (cmake -P): fails if any file of the source tree SOURCE_DIR points at the planning
# folder beside the repository (the sibling "shared" directory), which a user's clone does not
# have. The pattern is assembled so this file does not match itself.
set(parent "..")
set(pattern "${parent}/shared")
file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE ${SOURCE_DIR}
     ${SOURCE_DIR}/*.cpp ${SOURCE_DIR}/*.hpp ${SOURCE_DIR}/*.in ${SOURCE_DIR}/*.md ${SOURCE_DIR}/*.json
     ${SOURCE_DIR}/*.txt ${SOURCE_DIR}/*.cmake ${SOURCE_DIR}/*.sh ${SOURCE_DIR}/*.gp ${SOURCE_DIR}/*.csv)
set(offenders "")
foreach(file ${files})
  if(file MATCHES "^(build|\\.git)/" OR file MATCHES "/build/")
    continue()
  endif()
  file(READ ${SOURCE_DIR}/${file} text)
  string(FIND "${text}" "${pattern}" at)
  if(NOT at EQUAL -1)
    list(APPEND offenders ${file})
  endif()
endforeach()
list(LENGTH files count)
if(offenders)
  message(FATAL_ERROR "files that point outside the repository (${pattern}): ${offenders}")
endif()
message(STATUS "${count} files read; none points outside the repository")
