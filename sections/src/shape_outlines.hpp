#pragma once
// The outline of each shape family (one per file: i_shape.cpp, angle_tee_shapes.cpp,
// hollow_and_solid_shapes.cpp); shape_outline() dispatches to them.
#include "plascap/sections/shape_geometry.hpp"

namespace plascap {

RoundedOutline i_outline(const IShape& shape);
RoundedOutline channel_outline(const ChannelShape& shape);
RoundedOutline angle_outline(const AngleShape& shape);
RoundedOutline tee_outline(const TeeShape& shape);
RoundedOutline rectangular_hollow_outline(const RectangularHollowShape& shape);
RoundedOutline circular_hollow_outline(const CircularHollowShape& shape);
RoundedOutline round_bar_outline(const RoundBarShape& shape);
RoundedOutline flat_bar_outline(const FlatBarShape& shape);

}  // namespace plascap
