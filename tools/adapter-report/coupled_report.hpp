#pragma once
// adapter-report --coupled: the coupled yield scheme on every engine (docs/coupled-yield-report.md):
// the onset of flow against the exact condition, and where on the condition the joint flows as the
// time step changes.
#include <ostream>

namespace plascap::report {

// `plot`, if given, gets one line per case, engine and dt: case engine dt u_min u_mean u_max.
void coupled_report(std::ostream& md, std::ostream* plot);

}  // namespace plascap::report
