#pragma once
// What an engine's joint rows measure and can carry, which the law must know to plan them and to
// book their work. Bullet's 6-dof springs measure rotations as Euler angles and bound a motor row
// symmetrically; plascap's own Bullet constraint (bullet_plastic_constraint.hpp) and its own ODE
// joint (ode_plastic_rows.hpp) measure swing and twist and bound each row by both capacities.
namespace plascap {

enum class RotationMeasure : unsigned char {  // one byte: every joint law keeps one (issue 16)
    // θ of R = Rz(θz)·Ry(θy)·Rx(θx), rows about the Euler axes: engines switch to the triple's
    // second branch past |θy| = 90°, and a bending row does cos θy of work per unit of its angle.
    EulerXYZ,
    // swing_twist.hpp: twist about the beam axis y, swing vector in x–z; the rows are the exact
    // gradients, so a row's force is the generalised force of its angle. No branch, no factor.
    SwingTwist,
};

struct RowCapabilities {
    RotationMeasure rotations = RotationMeasure::EulerXYZ;
    // A Hold row carries the force range [lower, upper] (two capacities), not one symmetric bound.
    bool two_sided_bounds = false;
};

}  // namespace plascap
