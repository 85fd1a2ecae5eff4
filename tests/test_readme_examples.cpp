// The README's library examples are excerpts of examples/consumer/*.cpp, which consumer_find_package
// builds against an installed plascap and runs: every line of each excerpt (spaces at either end
// aside) must be a line of its file, in the same order, so the README cannot drift from code that
// compiles.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string trimmed(const std::string& line) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) return "";
    return line.substr(first, line.find_last_not_of(" \t") - first + 1);
}

std::vector<std::string> lines_of(const std::string& path) {
    std::ifstream in(path);
    EXPECT_TRUE(in) << "cannot read " << path;
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

TEST(Readme, LibraryExamplesAreExcerptsOfTheConsumerProject) {
    const std::string marker = "<!-- excerpt of ";
    const std::vector<std::string> readme = lines_of(PLASCAP_SOURCE_DIR "/README.md");
    int excerpts = 0;
    for (std::size_t i = 0; i < readme.size(); ++i) {
        if (readme[i].rfind(marker, 0) != 0) continue;
        ++excerpts;
        const std::string file = readme[i].substr(marker.size(), readme[i].find(" -->") - marker.size());
        std::vector<std::string> source;
        for (const std::string& line : lines_of(std::string(PLASCAP_SOURCE_DIR) + "/" + file)) source.push_back(trimmed(line));
        ASSERT_LT(i + 1, readme.size());
        ASSERT_EQ(readme[i + 1], "```cpp") << "README.md line " << i + 2 << ": the excerpt of " << file;
        std::size_t at = 0;  // where in the source the next line may be found
        for (std::size_t k = i + 2; k < readme.size() && readme[k] != "```"; ++k) {
            const std::string line = trimmed(readme[k]);
            if (line.empty()) continue;
            std::size_t found = at;
            while (found < source.size() && source[found] != line) ++found;
            EXPECT_LT(found, source.size()) << "README.md line " << k + 1 << " is not in " << file << " (after line " << at << "): " << line;
            if (found < source.size()) at = found + 1;
        }
    }
    EXPECT_EQ(excerpts, 4);  // Bullet, ODE, and a structure (built, then on Bullet)
}

}  // namespace
