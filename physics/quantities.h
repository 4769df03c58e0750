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
