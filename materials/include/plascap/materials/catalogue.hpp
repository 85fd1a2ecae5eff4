#pragma once
// Named materials. The built-in catalogue is materials/data/materials.json, compiled into the
// library (and installed as share/plascap/materials.json); users add their own files in the same
// format: {"format": "plascap-materials-1", "materials": [{"name": ..., "fy": ..., ...}, ...]}.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "plascap/materials/material.hpp"

namespace plascap {

class MaterialCatalogue {
public:
    // The catalogue shipped with plascap, every number with its source.
    static const MaterialCatalogue& built_in();
    // Throws InputError naming `origin` (a file name) and the entry for any problem, including a
    // name given twice in one file.
    static MaterialCatalogue parse(std::string_view json_text, const std::string& origin);
    static MaterialCatalogue read_file(const std::string& path);

    // Adds other's materials; one with the same name (ignoring case) replaces the existing one.
    void add(const MaterialCatalogue& other);

    // By name, ignoring case; nullptr when there is none.
    const Material* find(std::string_view name) const;
    // By name; throws InputError "WHERE: unknown material "S335" (did you mean S355, S235?)".
    const Material& get(std::string_view name, const std::string& where) const;
    // Up to `most` names close to `name` (edit distance, ignoring case), closest first.
    std::vector<std::string> similar_names(std::string_view name, std::size_t most = 3) const;

    const std::vector<Material>& materials() const { return materials_; }

private:
    std::vector<Material> materials_;
};

}  // namespace plascap
