#pragma once
// How section-calc shows a result: a table for people, one JSON object for programs.
#include <string>

#include "plascap/sections/capacities.hpp"
#include "plascap/sections/cubature.hpp"
#include "plascap/sections/elastic_properties.hpp"
#include "plascap/sections/valid_section.hpp"

namespace plascap::tools {

struct ReportContext {
    std::string source;  // file name or "--rect B x H"
    std::string method;  // "exact" or "cubature"
    const ValidSection* section = nullptr;
    const CubatureOptions* cubature_options = nullptr;  // with method "cubature"
    const CubatureResult* cubature = nullptr;           // error estimates, mesh size, time
    const ElasticProperties* elastic = nullptr;         // with --elastic
};

std::string capacity_table(const Capacities& capacities, const ReportContext& context);
std::string capacity_json(const Capacities& capacities, const ReportContext& context);

}  // namespace plascap::tools
