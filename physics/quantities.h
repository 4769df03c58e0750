// The catalogue of traced quantities: one place for each quantity's stable id, its
// symbol and formula in LaTeX, its frame and its unit. Sources of the formulas:
// TUM Game Physics "Simulation Algorithm 3D" (reference.md section 1).
#pragma once

#include "physics/trace.h"

namespace rbw::q {

// --- forces stage (algorithm step 1) ---
inline constexpr QuantityInfo gravity_force{
    "gravity_force", Stage::Forces, "M\\mathbf{g}", "M·g", "\\mathbf{f}_g = M\\,\\mathbf{g}",
    Frame::World, "N"};
inline constexpr QuantityInfo applied_force{
    "applied_force", Stage::Forces, "\\mathbf{f}_i", "fᵢ", "\\mathbf{f}_i", Frame::World, "N"};
inline constexpr QuantityInfo application_point{
    "application_point", Stage::Forces, "\\mathbf{p}_i", "pᵢ", "\\mathbf{p}_i", Frame::World, "m"};
inline constexpr QuantityInfo lever_arm{
    "lever_arm", Stage::Forces, "\\mathbf{x}_i", "xᵢ", "\\mathbf{x}_i = \\mathbf{p}_i - \\mathbf{x}",
    Frame::World, "m"};
inline constexpr QuantityInfo force{
    "force", Stage::Forces, "\\mathbf{F}", "F", "\\mathbf{F} = \\sum_i \\mathbf{f}_i", Frame::World, "N"};
inline constexpr QuantityInfo force_with_gravity{
    "force", Stage::Forces, "\\mathbf{F}", "F", "\\mathbf{F} = \\sum_i \\mathbf{f}_i + M\\,\\mathbf{g}",
    Frame::World, "N"};
inline constexpr QuantityInfo applied_torque{
    "applied_torque", Stage::Forces, "\\mathbf{q}_j", "qⱼ", "\\mathbf{q}_j", Frame::World, "N·m"};
inline constexpr QuantityInfo torque_with_couples{
    "torque", Stage::Forces, "\\mathbf{q}", "q",
    "\\mathbf{q} = \\sum_i \\mathbf{x}_i \\times \\mathbf{f}_i + \\sum_j \\mathbf{q}_j", Frame::World, "N·m"};
inline constexpr QuantityInfo torque{
    "torque", Stage::Forces, "\\mathbf{q}", "q", "\\mathbf{q} = \\sum_i \\mathbf{x}_i \\times \\mathbf{f}_i",
    Frame::World, "N·m"};

// --- integration stage (explicit Euler, algorithm steps 2-7) ---
inline constexpr QuantityInfo position{
    "position", Stage::Integration, "\\mathbf{x}", "x",
    "\\mathbf{x} \\leftarrow \\mathbf{x} + h\\,\\mathbf{v}", Frame::World, "m"};
inline constexpr QuantityInfo linear_velocity{
    "linear_velocity", Stage::Integration, "\\mathbf{v}", "v",
    "\\mathbf{v} \\leftarrow \\mathbf{v} + h\\,\\mathbf{F}/M", Frame::World, "m/s"};
inline constexpr QuantityInfo orientation{
    "orientation", Stage::Integration, "r", "r",
    "r \\leftarrow \\frac{r + \\frac{h}{2}\\,(0,\\boldsymbol{\\omega})\\,r}{\\lVert r + \\frac{h}{2}\\,(0,\\boldsymbol{\\omega})\\,r \\rVert}",
    Frame::World, ""};
inline constexpr QuantityInfo angular_momentum{
    "angular_momentum", Stage::Integration, "\\mathbf{L}", "L",
    "\\mathbf{L} \\leftarrow \\mathbf{L} + h\\,\\mathbf{q}", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo inertia_body{
    "inertia_body", Stage::Integration, "I_0", "I₀",
    "I_0 = \\tfrac{M}{12}\\operatorname{diag}(b^2+c^2,\\ a^2+c^2,\\ a^2+b^2)", Frame::Body, "kg·m²"};
inline constexpr QuantityInfo inverse_inertia_body{
    "inverse_inertia_body", Stage::Integration, "I_0^{-1}", "I₀⁻¹",
    "I_0^{-1} = \\operatorname{diag}(1/I_{0,xx},\\ 1/I_{0,yy},\\ 1/I_{0,zz})", Frame::Body, "1/(kg·m²)"};
inline constexpr QuantityInfo rotation_matrix{
    "rotation_matrix", Stage::Integration, "R", "R", "R = R(r)", Frame::World, ""};
inline constexpr QuantityInfo inverse_inertia_world{
    "inverse_inertia_world", Stage::Integration, "I^{-1}", "I⁻¹",
    "I^{-1} = R\\,I_0^{-1}\\,R^{\\mathsf{T}}", Frame::World, "1/(kg·m²)"};
inline constexpr QuantityInfo inverse_inertia_world_template{
    "inverse_inertia_world", Stage::Integration, "I^{-1}", "I⁻¹",
    "I^{-1} = R^{\\mathsf{T}}\\,I_0^{-1}\\,R", Frame::World, "1/(kg·m²)"};
inline constexpr QuantityInfo angular_velocity{
    "angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}", "ω",
    "\\boldsymbol{\\omega} = I^{-1}\\,\\mathbf{L}", Frame::World, "rad/s"};

// --- probes (algorithm step 8) ---
inline constexpr QuantityInfo probe_position{
    "probe_position", Stage::Probes, "\\mathbf{p}", "p",
    "\\mathbf{p} = \\mathbf{x} + R\\,\\mathbf{p}_B", Frame::World, "m"};
inline constexpr QuantityInfo point_velocity{
    "point_velocity", Stage::Probes, "\\mathbf{v}_p", "v_p",
    "\\mathbf{v}_p = \\mathbf{v} + \\boldsymbol{\\omega} \\times (\\mathbf{p} - \\mathbf{x})",
    Frame::World, "m/s"};

} // namespace rbw::q

namespace rbw::q {

// --- collision stage (reference.md sections 2-3) ---
// World-level broad-phase counts (body -1).
inline constexpr QuantityInfo pairs_tested{
    "pairs_tested", Stage::Collision, "N_{\\text{tested}}", "N",
    "\\text{AABB pairs tested by sweep-and-prune}", Frame::None, ""};
inline constexpr QuantityInfo pairs_overlapping{
    "pairs_overlapping", Stage::Collision, "N_{\\text{overlap}}", "N",
    "\\text{AABB pairs that overlap (sent to SAT)}", Frame::None, ""};
// Per contact (index = contact number).
inline constexpr QuantityInfo contact_point{
    "point", Stage::Collision, "\\mathbf{p}", "p", "\\mathbf{p}\\ \\text{(contact point)}", Frame::World, "m"};
inline constexpr QuantityInfo contact_normal{
    "normal", Stage::Collision, "\\mathbf{n}", "n", "\\mathbf{n}\\ \\text{(unit, from B to A)}", Frame::World, ""};
inline constexpr QuantityInfo contact_depth{
    "depth", Stage::Collision, "d", "d", "d\\ \\text{(penetration, not used by } J)", Frame::None, "m"};
inline constexpr QuantityInfo x_a{
    "x_a", Stage::Collision, "\\mathbf{x}_a", "x_a", "\\mathbf{x}_a = \\mathbf{p} - \\mathbf{x}_A", Frame::World, "m"};
inline constexpr QuantityInfo x_b{
    "x_b", Stage::Collision, "\\mathbf{x}_b", "x_b", "\\mathbf{x}_b = \\mathbf{p} - \\mathbf{x}_B", Frame::World, "m"};
inline constexpr QuantityInfo velocity_a{
    "velocity_a", Stage::Collision, "\\mathbf{v}_A(\\mathbf{p})", "v_A(p)",
    "\\mathbf{v}_A(\\mathbf{p}) = \\mathbf{v}_A + \\boldsymbol{\\omega}_A \\times \\mathbf{x}_a", Frame::World, "m/s"};
inline constexpr QuantityInfo velocity_b{
    "velocity_b", Stage::Collision, "\\mathbf{v}_B(\\mathbf{p})", "v_B(p)",
    "\\mathbf{v}_B(\\mathbf{p}) = \\mathbf{v}_B + \\boldsymbol{\\omega}_B \\times \\mathbf{x}_b", Frame::World, "m/s"};
inline constexpr QuantityInfo relative_velocity{
    "relative_velocity", Stage::Collision, "\\mathbf{v}_{\\text{rel}}", "v_rel",
    "\\mathbf{v}_{\\text{rel}} = \\mathbf{v}_A(\\mathbf{p}) - \\mathbf{v}_B(\\mathbf{p})", Frame::World, "m/s"};
inline constexpr QuantityInfo normal_velocity{
    "normal_velocity", Stage::Collision, "\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}", "v_rel·n",
    "\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}\\ (> 0:\\ \\text{separating, no impulse})", Frame::None, "m/s"};
inline constexpr QuantityInfo restitution{
    "restitution", Stage::Collision, "c", "c", "c\\ \\text{(coefficient of restitution)}", Frame::None, ""};
inline constexpr QuantityInfo numerator{
    "numerator", Stage::Collision, "-(1+c)\\,\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}", "−(1+c) v_rel·n",
    "-(1+c)\\,\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}", Frame::None, "m/s"};
inline constexpr QuantityInfo inv_mass_a{
    "inv_mass_a", Stage::Collision, "1/M_A", "1/M_A", "1/M_A", Frame::None, "1/kg"};
inline constexpr QuantityInfo inv_mass_b{
    "inv_mass_b", Stage::Collision, "1/M_B", "1/M_B", "1/M_B\\ (0\\ \\text{if fixed})", Frame::None, "1/kg"};
inline constexpr QuantityInfo rotational_a{
    "rotational_a", Stage::Collision, "[\\cdot]_A", "[(I_A⁻¹(x_a×n))×x_a]·n",
    "\\big[(I_A^{-1}(\\mathbf{x}_a\\times\\mathbf{n}))\\times\\mathbf{x}_a\\big]\\cdot\\mathbf{n}", Frame::None, "1/kg"};
inline constexpr QuantityInfo rotational_b{
    "rotational_b", Stage::Collision, "[\\cdot]_B", "[(I_B⁻¹(x_b×n))×x_b]·n",
    "\\big[(I_B^{-1}(\\mathbf{x}_b\\times\\mathbf{n}))\\times\\mathbf{x}_b\\big]\\cdot\\mathbf{n}", Frame::None, "1/kg"};
inline constexpr QuantityInfo denominator{
    "denominator", Stage::Collision, "k_n", "1/M_A + 1/M_B + [·]_A + [·]_B",
    "\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_A + [\\cdot]_B", Frame::None, "1/kg"};
inline constexpr QuantityInfo impulse{
    "impulse", Stage::Collision, "J", "J",
    "J = \\frac{-(1+c)\\,\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}}{\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_A + [\\cdot]_B}",
    Frame::None, "N·s"};
inline constexpr QuantityInfo friction_impulse{
    "friction_impulse", Stage::Collision, "J_t\\,\\mathbf{t}", "J_t t",
    "J_t = \\min\\!\\Big(\\frac{|\\mathbf{v}_{\\text{rel},t}|}{\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_{A,t} + [\\cdot]_{B,t}},\\ \\mu J\\Big)",
    Frame::World, "N·s"};
inline constexpr QuantityInfo friction_coefficient{
    "friction_coefficient", Stage::Collision, "\\mu", "μ", "\\mu\\ \\text{(Coulomb friction coefficient)}",
    Frame::None, ""};
inline constexpr QuantityInfo sliding{
    "sliding", Stage::Collision, "s", "sliding",
    "s = 1\\ \\text{if}\\ J_t^{*} > \\mu J\\ \\text{(slides, } J_t = \\mu J),\\ 0\\ \\text{if it sticks}",
    Frame::None, ""};
inline constexpr QuantityInfo delta_v_a{
    "delta_v_a", Stage::Collision, "\\Delta\\mathbf{v}_A", "Δv_A",
    "\\Delta\\mathbf{v}_A = (J\\,\\mathbf{n} + J_t\\mathbf{t})/M_A", Frame::World, "m/s"};
inline constexpr QuantityInfo delta_v_b{
    "delta_v_b", Stage::Collision, "\\Delta\\mathbf{v}_B", "Δv_B",
    "\\Delta\\mathbf{v}_B = -(J\\,\\mathbf{n} + J_t\\mathbf{t})/M_B", Frame::World, "m/s"};
inline constexpr QuantityInfo delta_L_a{
    "delta_L_a", Stage::Collision, "\\Delta\\mathbf{L}_A", "ΔL_A",
    "\\Delta\\mathbf{L}_A = \\mathbf{x}_a \\times (J\\,\\mathbf{n} + J_t\\mathbf{t})", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo delta_L_b{
    "delta_L_b", Stage::Collision, "\\Delta\\mathbf{L}_B", "ΔL_B",
    "\\Delta\\mathbf{L}_B = -\\mathbf{x}_b \\times (J\\,\\mathbf{n} + J_t\\mathbf{t})", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo linear_velocity_a{
    "linear_velocity_a", Stage::Collision, "\\mathbf{v}_A'", "v_A'",
    "\\mathbf{v}_A' = \\mathbf{v}_A + \\Delta\\mathbf{v}_A", Frame::World, "m/s"};
inline constexpr QuantityInfo linear_velocity_b{
    "linear_velocity_b", Stage::Collision, "\\mathbf{v}_B'", "v_B'",
    "\\mathbf{v}_B' = \\mathbf{v}_B + \\Delta\\mathbf{v}_B", Frame::World, "m/s"};
inline constexpr QuantityInfo angular_momentum_a{
    "angular_momentum_a", Stage::Collision, "\\mathbf{L}_A'", "L_A'",
    "\\mathbf{L}_A' = \\mathbf{L}_A + \\Delta\\mathbf{L}_A", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo angular_momentum_b{
    "angular_momentum_b", Stage::Collision, "\\mathbf{L}_B'", "L_B'",
    "\\mathbf{L}_B' = \\mathbf{L}_B + \\Delta\\mathbf{L}_B", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo angular_velocity_a{
    "angular_velocity_a", Stage::Collision, "\\boldsymbol{\\omega}_A'", "ω_A'",
    "\\boldsymbol{\\omega}_A' = I_A^{-1}\\,\\mathbf{L}_A'", Frame::World, "rad/s"};
inline constexpr QuantityInfo angular_velocity_b{
    "angular_velocity_b", Stage::Collision, "\\boldsymbol{\\omega}_B'", "ω_B'",
    "\\boldsymbol{\\omega}_B' = I_B^{-1}\\,\\mathbf{L}_B'", Frame::World, "rad/s"};
inline constexpr QuantityInfo kinetic_energy_before{
    "kinetic_energy_before", Stage::Collision, "T", "T",
    "T = \\sum_{A,B} \\tfrac12 M|\\mathbf{v}|^2 + \\tfrac12\\boldsymbol{\\omega}\\cdot\\mathbf{L}", Frame::None, "J"};
inline constexpr QuantityInfo kinetic_energy_after{
    "kinetic_energy_after", Stage::Collision, "T'", "T'",
    "T' = \\sum_{A,B} \\tfrac12 M|\\mathbf{v}'|^2 + \\tfrac12\\boldsymbol{\\omega}'\\cdot\\mathbf{L}'", Frame::None, "J"};

// --- correction stage: not part of the impulse formula ---
inline constexpr QuantityInfo correction_a{
    "correction_a", Stage::Correction, "\\Delta\\mathbf{x}_A", "Δx_A",
    "\\Delta\\mathbf{x}_A = d\\,\\mathbf{n}\\,\\frac{1/M_A}{1/M_A + 1/M_B}", Frame::World, "m"};
inline constexpr QuantityInfo correction_b{
    "correction_b", Stage::Correction, "\\Delta\\mathbf{x}_B", "Δx_B",
    "\\Delta\\mathbf{x}_B = -d\\,\\mathbf{n}\\,\\frac{1/M_B}{1/M_A + 1/M_B}", Frame::World, "m"};

} // namespace rbw::q
