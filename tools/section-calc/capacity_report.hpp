#pragma once
// How section-calc shows a result: a table for people, one JSON object for programs.
#include <nlohmann/json.hpp>
#include <string>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/joint_stiffness.hpp"
#include "plascap/sections/plastic_torsion.hpp"
#include "plascap/sections/torsion_constant.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap::tools {

struct ReportContext {
    std::string source;  // file name or "--rect B x H"
    std::string method;  // "exact" or "cubature"
    const ValidSection* section = nullptr;
    const CubatureOptions* cubature_options = nullptr;  // with method "cubature"
    const CubatureResult* cubature = nullptr;           // error estimates, mesh size, time
    const ElasticProperties* elastic = nullptr;         // with --elastic
    const TorsionConstant* torsion = nullptr;           // with --elastic: J
    const PlasticTorsion* plastic_torsion = nullptr;    // with --elastic: T_p
    const JointStiffness* joint = nullptr;              // with --length
    double length = 0.0;                                // [m], with --length
};

std::string capacity_table(const Capacities& capacities, const ReportContext& context);
std::string capacity_json(const Capacities& capacities, const ReportContext& context);
nlohmann::ordered_json capacity_json_value(const Capacities& capacities, const ReportContext& context);

}  // namespace plascap::tools
