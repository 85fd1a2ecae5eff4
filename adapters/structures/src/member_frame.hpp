#pragma once
// A member's axes and their rotation (docs/structures.md): y along it from `from` to `to`, z the
// section's depth, x = y × z.
#include <optional>
#include <string>

#include "plascap/adapters/structure_model.hpp"

namespace plascap::detail {

struct MemberFrame {
    Vec3 x, y, z;
    MemberFrame reversed() const { return {x, scaled(y, -1.0), scaled(z, -1.0)}; }  // y the other way, still right-handed
};

// `along` a unit vector; z is `z_axis` made square to it (none: against gravity, or world x for a
// member along gravity). Throws InputError "<where>.z_axis: ..." when z_axis is zero or along y.
MemberFrame member_frame(const std::optional<Vec3>& z_axis, const Vec3& along, const Vec3& gravity, const std::string& where);

// The rotation whose columns are the frame's axes, as a unit quaternion.
Quaternion quaternion_of(const MemberFrame& f);

}  // namespace plascap::detail
