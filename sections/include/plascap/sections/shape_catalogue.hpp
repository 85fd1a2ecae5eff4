#pragma once
// The catalogue of standard shapes (sections/data/shapes.json, compiled in and installed under
// share/plascap/): families of rows, each row a designation, the generator's geometry and the
// values its table publishes, with the table's source. Lookup by designation is forgiving about
// case, spaces and the HE spelling: "IPE300", "ipe 300", "HE 200 B", "HEB200", "chs 168.3x8".
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "plascap/sections/shape_geometry.hpp"

namespace plascap {

// A value as the table prints it: `resolution` is one unit of its last printed digit, so the
// printed number stands for value ± resolution/2.
struct PublishedValue {
    double value = 0.0;       // SI
    double resolution = 0.0;  // SI
};

struct CatalogueShape {
    std::string designation;  // as printed, e.g. "IPE 300", "HEB 200", "CHS 168.3x8"
    std::string family;       // e.g. "HEB"
    ShapeGeometry geometry;
    // Keys: A, Iy, Iz (EN axes: y–y strong = plascap's x), Wel_y, Wel_z, Wpl_y, Wpl_z, It, Iw, and
    // family-specific ones (docs/shapes.md). Only what the table prints.
    std::map<std::string, PublishedValue> published;
};

struct ShapeFamily {
    std::string name;         // "IPE"
    std::string kind;         // the generator: I, channel, angle, rectangular_hollow, circular_hollow
    std::string standard;     // "EN 10365:2017"
    std::string description;
    std::string source;       // where the rows' numbers come from
    std::vector<CatalogueShape> shapes;
};

class ShapeCatalogue {
public:
    static const ShapeCatalogue& built_in();
    // `origin` names the text in messages. Throws InputError on any malformed row.
    static ShapeCatalogue parse(std::string_view json_text, const std::string& origin);

    const std::vector<ShapeFamily>& families() const { return families_; }
    const ShapeFamily* family(std::string_view name) const;        // case-insensitive; nullptr if none
    const CatalogueShape* find(std::string_view designation) const;  // nullptr if none
    // Up to `count` designations closest to `designation` (edit distance of the lookup keys).
    std::vector<std::string> suggestions(std::string_view designation, std::size_t count = 3) const;
    std::size_t size() const;

private:
    std::vector<ShapeFamily> families_;
    std::map<std::string, std::pair<std::size_t, std::size_t>> index_;  // lookup key → (family, row)
};

// The lookup key of a designation: upper case, without spaces, '-' or '_', '×' and '*' as 'X',
// ',' as '.', and "HE 200 B" as "HEB200".
std::string designation_key(std::string_view designation);

}  // namespace plascap
