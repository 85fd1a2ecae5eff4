#pragma once
// The six degrees of freedom of a joint, in plascap's joint frame (README, "What it computes";
// paper Fig. 2.2): y is the beam (joint) axis, the section lies in x–z. A dof's position is the motion of body b relative to body a:
// translation of b's anchor along the axis [m], or rotation of b about it (right-hand rule) [rad].
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace plascap {

enum class Dof : std::size_t {
    Qx = 0,  // translation along x: shear
    N = 1,   // translation along y: axial
    Qz = 2,  // translation along z: shear
    Mx = 3,  // rotation about x: bending (stress varies with z)
    My = 4,  // rotation about y: torsion
    Mz = 5,  // rotation about z: bending (stress varies with x)
};
inline constexpr std::size_t kDofCount = 6;

template <typename T>
using PerDof = std::array<T, kDofCount>;

inline constexpr PerDof<Dof> kAllDofs = {Dof::Qx, Dof::N, Dof::Qz, Dof::Mx, Dof::My, Dof::Mz};

constexpr std::size_t index(Dof dof) { return static_cast<std::size_t>(dof); }
constexpr bool is_rotation(Dof dof) { return index(dof) >= 3; }
// The joint-frame axis of a dof: 0 = x, 1 = y, 2 = z.
constexpr std::size_t axis_of(Dof dof) { return index(dof) % 3; }

// "N", "Qx", ...: the names scenes and reports use.
const char* dof_name(Dof dof);
// Throws InputError naming `where` for an unknown name.
Dof dof_from_name(const std::string& name, const std::string& where);

// What a joint does in a dof. Only rigid and plastic dofs get constraint rows.
enum class DofMode : std::uint8_t {  // one byte: each joint law keeps six (issue 16)
    Free,     // no row: the dof moves without resistance
    Rigid,    // a locked row: no motion, unlimited force
    Plastic,  // a force-limited row driven by the dof's ElasticPlasticLaw
};
const char* dof_mode_name(DofMode mode);
DofMode dof_mode_from_name(const std::string& name, const std::string& where);

}  // namespace plascap
