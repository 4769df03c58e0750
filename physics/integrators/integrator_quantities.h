// Trace quantities of the integrators beyond explicit Euler (physics/quantities.h):
// the RK stages, the Newton solves of the implicit methods, the rotation-matrix
// update of Napier practical 6. Same style as quantities.h: a stable id, the symbol
// and formula in LaTeX, a plain-text symbol, the frame and the unit.
//
// A quantity that several integrators compute with different formulas (the new
// position, orientation, ...) keeps the id of quantities.h ("position", ...) and gets
// its own QuantityInfo with the formula of that method, as force_with_gravity does.
//
// Index convention: RK stage quantities carry the stage number i = 1..4 as their
// index (k1 = index 1); everything else has index -1.
//
// Sources: Hairer, Lubich & Wanner, "Geometric Numerical Integration" (2nd ed.),
// sections II.1 (RK methods), IV.2 (quadratic invariants), VII.5.3 (rigid body,
// implicit midpoint + Cayley); Catto, "Numerical Methods", GDC 2015 (gyroscopic
// term); Napier SET09119 practical 6 (rotation matrix); reference.md sections 1, 4, 5.
#pragma once

#include "physics/trace.h"

namespace rbw::q {

// --- shared by several integrators ---
inline constexpr QuantityInfo gyroscopic_skipped{
    "gyroscopic_skipped", Stage::Integration, "I_0 = k\\,E", "I₀ = k·E",
    "I_0 = k\\,E \\;\\Rightarrow\\; \\boldsymbol{\\omega}\\times I_0\\boldsymbol{\\omega} = 0\\ \\text{(gyroscopic work skipped)}",
    Frame::Body, ""};

// --- symplectic Euler: velocities first, then positions with the new ones ---
inline constexpr QuantityInfo se_linear_velocity{
    "linear_velocity", Stage::Integration, "\\mathbf{v}", "v",
    "\\mathbf{v}_{n+1} = \\mathbf{v}_n + h\\,\\mathbf{F}/M", Frame::World, "m/s"};
inline constexpr QuantityInfo se_position{
    "position", Stage::Integration, "\\mathbf{x}", "x",
    "\\mathbf{x}_{n+1} = \\mathbf{x}_n + h\\,\\mathbf{v}_{n+1}", Frame::World, "m"};
inline constexpr QuantityInfo se_angular_momentum{
    "angular_momentum", Stage::Integration, "\\mathbf{L}", "L",
    "\\mathbf{L}_{n+1} = \\mathbf{L}_n + h\\,\\mathbf{q}", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo update_angular_velocity{
    "update_angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}'", "ω'",
    "\\boldsymbol{\\omega}' = I^{-1}(r_n)\\,\\mathbf{L}_{n+1}", Frame::World, "rad/s"};
inline constexpr QuantityInfo se_orientation{
    "orientation", Stage::Integration, "r", "r",
    "r_{n+1} = \\frac{r_n + \\frac{h}{2}(0,\\boldsymbol{\\omega}')\\,r_n}{\\lVert\\cdot\\rVert}", Frame::World, ""};

// --- explicit Runge-Kutta (midpoint, RK4) on y = (x, r, P, L) ---
inline constexpr QuantityInfo stage_velocity{
    "stage_velocity", Stage::Integration, "\\mathbf{k}_{x,i}", "k_x,i",
    "\\mathbf{k}_{x,i} = \\dot{\\mathbf{x}}(Y_i) = \\mathbf{v}_i", Frame::World, "m/s"};
inline constexpr QuantityInfo stage_angular_velocity{
    "stage_angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}_i", "ω_i",
    "\\boldsymbol{\\omega}_i = I^{-1}(r_i)\\,\\mathbf{L}_i", Frame::World, "rad/s"};
inline constexpr QuantityInfo stage_orientation_rate{
    "stage_orientation_rate", Stage::Integration, "k_{r,i}", "k_r,i",
    "k_{r,i} = \\dot r(Y_i) = \\tfrac12\\,(0,\\boldsymbol{\\omega}_i)\\,r_i", Frame::World, "1/s"};
inline constexpr QuantityInfo stage_torque{
    "stage_torque", Stage::Integration, "\\mathbf{k}_{L,i}", "k_L,i",
    "\\mathbf{k}_{L,i} = \\dot{\\mathbf{L}}(Y_i) = \\mathbf{q}", Frame::World, "N·m"};
inline constexpr QuantityInfo midpoint_position{
    "position", Stage::Integration, "\\mathbf{x}", "x",
    "\\mathbf{x}_{n+1} = \\mathbf{x}_n + h\\,\\mathbf{k}_{x,2}", Frame::World, "m"};
inline constexpr QuantityInfo midpoint_linear_velocity{
    "linear_velocity", Stage::Integration, "\\mathbf{v}", "v",
    "\\mathbf{v}_{n+1} = \\mathbf{v}_n + h\\,\\mathbf{F}/M", Frame::World, "m/s"};
inline constexpr QuantityInfo midpoint_orientation{
    "orientation", Stage::Integration, "r", "r",
    "r_{n+1} = \\frac{r_n + h\\,k_{r,2}}{\\lVert\\cdot\\rVert}", Frame::World, ""};
inline constexpr QuantityInfo midpoint_angular_momentum{
    "angular_momentum", Stage::Integration, "\\mathbf{L}", "L",
    "\\mathbf{L}_{n+1} = \\mathbf{L}_n + h\\,\\mathbf{k}_{L,2}", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo rk4_position{
    "position", Stage::Integration, "\\mathbf{x}", "x",
    "\\mathbf{x}_{n+1} = \\mathbf{x}_n + \\tfrac{h}{6}(\\mathbf{k}_{x,1} + 2\\mathbf{k}_{x,2} + 2\\mathbf{k}_{x,3} + \\mathbf{k}_{x,4})",
    Frame::World, "m"};
inline constexpr QuantityInfo rk4_linear_velocity{
    "linear_velocity", Stage::Integration, "\\mathbf{v}", "v",
    "\\mathbf{v}_{n+1} = \\mathbf{v}_n + h\\,\\mathbf{F}/M", Frame::World, "m/s"};
inline constexpr QuantityInfo rk4_orientation{
    "orientation", Stage::Integration, "r", "r",
    "r_{n+1} = \\frac{r_n + \\frac{h}{6}(k_{r,1} + 2k_{r,2} + 2k_{r,3} + k_{r,4})}{\\lVert\\cdot\\rVert}",
    Frame::World, ""};
inline constexpr QuantityInfo rk4_angular_momentum{
    "angular_momentum", Stage::Integration, "\\mathbf{L}", "L",
    "\\mathbf{L}_{n+1} = \\mathbf{L}_n + \\tfrac{h}{6}(\\mathbf{k}_{L,1} + 2\\mathbf{k}_{L,2} + 2\\mathbf{k}_{L,3} + \\mathbf{k}_{L,4})",
    Frame::World, "kg·m²/s"};

// --- implicit gyroscopic (Catto GDC 2015; Bullet computeGyroscopicImpulseImplicit_Body) ---
inline constexpr QuantityInfo body_angular_velocity{
    "body_angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}_B", "ω_B",
    "\\boldsymbol{\\omega}_B = R^{\\mathsf{T}}\\boldsymbol{\\omega}", Frame::Body, "rad/s"};
inline constexpr QuantityInfo gyroscopic_jacobian{
    "gyroscopic_jacobian", Stage::Integration, "J", "J",
    "J = I_0 + h\\,\\big([\\boldsymbol{\\omega}_B]_\\times I_0 - [I_0\\boldsymbol{\\omega}_B]_\\times\\big)",
    Frame::Body, "kg·m²"};
inline constexpr QuantityInfo body_angular_velocity_new{
    "body_angular_velocity_new", Stage::Integration, "\\boldsymbol{\\omega}_B'", "ω_B'",
    "\\boldsymbol{\\omega}_B' = \\boldsymbol{\\omega}_B - J^{-1}\\,h\\,\\boldsymbol{\\omega}_B\\times I_0\\boldsymbol{\\omega}_B",
    Frame::Body, "rad/s"};
inline constexpr QuantityInfo newton_iterations{
    "newton_iterations", Stage::Integration, "n_{\\text{Newton}}", "n",
    "n_{\\text{Newton}}\\ \\text{(Newton updates taken)}", Frame::None, ""};
inline constexpr QuantityInfo gyroscopic_residual{
    "newton_residual", Stage::Integration, "\\lVert\\mathbf{g}\\rVert", "|g|",
    "\\mathbf{g} = I_0(\\boldsymbol{\\omega}_B' - \\boldsymbol{\\omega}_B) + h\\,\\boldsymbol{\\omega}_B'\\times I_0\\boldsymbol{\\omega}_B'",
    Frame::None, "kg·m²/s"};
inline constexpr QuantityInfo gyroscopic_angular_velocity{
    "update_angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}'", "ω'",
    "\\boldsymbol{\\omega}' = R\\,\\boldsymbol{\\omega}_B' + h\\,I^{-1}\\mathbf{q}", Frame::World, "rad/s"};
inline constexpr QuantityInfo gyroscopic_angular_momentum{
    "angular_momentum", Stage::Integration, "\\mathbf{L}", "L",
    "\\mathbf{L}_{n+1} = R_{n+1} I_0 R_{n+1}^{\\mathsf{T}}\\,\\boldsymbol{\\omega}'", Frame::World, "kg·m²/s"};

// --- implicit midpoint (Lie-Poisson form in the body frame + Cayley rotation) ---
inline constexpr QuantityInfo body_angular_momentum{
    "body_angular_momentum", Stage::Integration, "\\mathbf{L}_B", "L_B",
    "\\mathbf{L}_B = R^{\\mathsf{T}}\\mathbf{L}", Frame::Body, "kg·m²/s"};
inline constexpr QuantityInfo body_angular_momentum_new{
    "body_angular_momentum_new", Stage::Integration, "\\mathbf{L}_B'", "L_B'",
    "\\mathbf{L}_B' = \\mathbf{L}_B - h\\,\\boldsymbol{\\omega}_m\\times\\mathbf{L}_m,\\ \\mathbf{L}_m = \\tfrac12(\\mathbf{L}_B + \\mathbf{L}_B'),\\ \\boldsymbol{\\omega}_m = I_0^{-1}\\mathbf{L}_m",
    Frame::Body, "kg·m²/s"};
inline constexpr QuantityInfo midpoint_body_angular_velocity{
    "midpoint_angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}_m", "ω_m",
    "\\boldsymbol{\\omega}_m = I_0^{-1}\\,\\tfrac12(\\mathbf{L}_B + \\mathbf{L}_B')", Frame::Body, "rad/s"};
inline constexpr QuantityInfo midpoint_world_angular_velocity{
    "midpoint_angular_velocity", Stage::Integration, "\\boldsymbol{\\omega}_m", "ω_m",
    "\\boldsymbol{\\omega}_m = I^{-1}(r_m)\\,\\mathbf{L},\\ r_m = \\tfrac12(r_n + r_{n+1})", Frame::World, "rad/s"};
inline constexpr QuantityInfo midpoint_newton_residual{
    "newton_residual", Stage::Integration, "\\lVert\\mathbf{G}\\rVert", "|G|",
    "\\mathbf{G} = \\mathbf{L}_B' - \\mathbf{L}_B + h\\,\\boldsymbol{\\omega}_m\\times\\mathbf{L}_m", Frame::None,
    "kg·m²/s"};
inline constexpr QuantityInfo fixed_point_iterations{
    "newton_iterations", Stage::Integration, "n_{\\text{iter}}", "n",
    "n_{\\text{iter}}\\ \\text{(fixed-point iterations on } \\boldsymbol{\\omega}_m)", Frame::None, ""};
inline constexpr QuantityInfo fixed_point_residual{
    "newton_residual", Stage::Integration, "\\lVert\\Delta\\boldsymbol{\\omega}_m\\rVert", "|Δω_m|",
    "\\lVert\\boldsymbol{\\omega}_m^{(k+1)} - \\boldsymbol{\\omega}_m^{(k)}\\rVert", Frame::None, "rad/s"};
inline constexpr QuantityInfo cayley_rotation{
    "cayley_rotation", Stage::Integration, "c", "c",
    "c = \\frac{(1,\\ \\tfrac{h}{2}\\boldsymbol{\\omega}_m)}{\\lVert(1,\\ \\tfrac{h}{2}\\boldsymbol{\\omega}_m)\\rVert} \\;=\\; \\operatorname{cay}(h[\\boldsymbol{\\omega}_m]_\\times)",
    Frame::Body, ""};
inline constexpr QuantityInfo cayley_orientation{
    "orientation", Stage::Integration, "r", "r", "r_{n+1} = r_n\\,c", Frame::World, ""};
inline constexpr QuantityInfo cayley_world_orientation{
    "orientation", Stage::Integration, "r", "r",
    "r_{n+1} = r_n + \\tfrac{h}{2}(0,\\boldsymbol{\\omega}_m)\\,\\tfrac12(r_n + r_{n+1})", Frame::World, ""};
inline constexpr QuantityInfo half_kick_angular_momentum{
    "angular_momentum", Stage::Integration, "\\mathbf{L}", "L",
    "\\mathbf{L}_{n+1} = \\mathbf{L}_n + \\tfrac{h}{2}\\mathbf{q} + \\tfrac{h}{2}\\mathbf{q}", Frame::World, "kg·m²/s"};
inline constexpr QuantityInfo verlet_position{
    "position", Stage::Integration, "\\mathbf{x}", "x",
    "\\mathbf{x}_{n+1} = \\mathbf{x}_n + h\\,(\\mathbf{v}_n + \\tfrac{h}{2}\\mathbf{F}/M)", Frame::World, "m"};
inline constexpr QuantityInfo verlet_linear_velocity{
    "linear_velocity", Stage::Integration, "\\mathbf{v}", "v",
    "\\mathbf{v}_{n+1} = \\mathbf{v}_n + \\tfrac{h}{2}\\mathbf{F}/M + \\tfrac{h}{2}\\mathbf{F}/M", Frame::World, "m/s"};

// --- rotation matrix (Napier practical 6) ---
inline constexpr QuantityInfo rotation_matrix_update{
    "rotation_matrix_update", Stage::Integration, "R + h[\\boldsymbol{\\omega}]_\\times R", "R + h[ω]×R",
    "R_{n+1} = R_n + h\\,[\\boldsymbol{\\omega}_n]_\\times R_n", Frame::World, ""};
inline constexpr QuantityInfo orthonormality_error_before{
    "orthonormality_error_before", Stage::Integration, "\\lVert R^{\\mathsf{T}}R - E\\rVert_F", "‖RᵀR − E‖ (before)",
    "\\lVert R^{\\mathsf{T}}R - E\\rVert_F\\ \\text{of}\\ R_n + h[\\boldsymbol{\\omega}]_\\times R_n", Frame::None, ""};
inline constexpr QuantityInfo polar_rotation_matrix{
    "rotation_matrix", Stage::Integration, "R", "R",
    "R \\leftarrow U V^{\\mathsf{T}},\\ U\\Sigma V^{\\mathsf{T}} = R_n + h[\\boldsymbol{\\omega}]_\\times R_n\\ \\text{(nearest rotation)}",
    Frame::World, ""};
inline constexpr QuantityInfo drifting_rotation_matrix{
    "rotation_matrix", Stage::Integration, "R", "R",
    "R \\leftarrow R_n + h[\\boldsymbol{\\omega}]_\\times R_n\\ \\text{(not orthonormalised)}", Frame::World, ""};
inline constexpr QuantityInfo orthonormality_error{
    "orthonormality_error", Stage::Integration, "\\lVert R^{\\mathsf{T}}R - E\\rVert_F", "‖RᵀR − E‖",
    "\\lVert R^{\\mathsf{T}}R - E\\rVert_F", Frame::None, ""};
inline constexpr QuantityInfo rotation_determinant{
    "rotation_determinant", Stage::Integration, "\\det R", "det R", "\\det R\\ (1\\ \\text{for a rotation})",
    Frame::None, ""};
inline constexpr QuantityInfo orientation_from_matrix{
    "orientation", Stage::Integration, "r", "r",
    "r = r(R)\\ \\text{(read from } R\\text{, normalised)}", Frame::World, ""};

} // namespace rbw::q
