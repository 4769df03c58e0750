// The one catalogue of traced quantities: every number the physics records, with its
// stable trace id, its display name (the app's table), its stage, what its index counts, its symbol and formula in LaTeX, a
// plain UTF-8 symbol for tables, its frame and its unit. The physics records entries
// that point into this table (through the named handles of quantities.h); the trace,
// the CLI (`rbw quantities`, JSON and CSV), the derivation templates and the app's table
// all read it, and nothing else spells a quantity's id.
//
// A quantity that is computed with different formulas (by different integrators, with
// or without gravity, in the two inertia conventions) has one row per formula: the rows
// share the trace id and differ in their unique key, so a view shows the formula that
// was actually used.
//
// Sources of the formulas: TUM Game Physics "Simulation Algorithm 3D" and the impulse
// slides (docs/references.md §1, §3), the template's SAT (§2), Napier practicals (§4),
// Hairer, Lubich & Wanner (sections II.1, IV.2, VII.5), Catto GDC 2015 (gyroscopic
// term) - see docs/references.md.
#pragma once

#include "physics/engine/quantity_rows_integrators.h"
#include "physics/engine/trace.h"

#include <span>
#include <array>
#include <string_view>

namespace rbw {

// clang-format off
// The engine's rows: forces, the base integration rows (explicit Euler), probes, the
// collision and correction stages and the manifold model. The integrators' own rows
// follow them in quantity_rows_integrators.h (one table, split to keep files short).
inline constexpr QuantityInfo kEngineQuantityRows[] = {
    // --- forces stage (algorithm step 1) ---
    {"gravity_force", "gravity_force", "gravity force", Stage::Forces, IndexKind::None, "M\\mathbf{g}", "M·g",
     "\\mathbf{f}_g = M\\,\\mathbf{g}", Frame::World, "N"},
    {"applied_force", "applied_force", "applied force", Stage::Forces, IndexKind::Force, "\\mathbf{f}_i", "fᵢ",
     "\\mathbf{f}_i", Frame::World, "N"},
    {"application_point", "application_point", "application point", Stage::Forces, IndexKind::Force, "\\mathbf{p}_i", "pᵢ",
     "\\mathbf{p}_i", Frame::World, "m"},
    {"lever_arm", "lever_arm", "lever arm", Stage::Forces, IndexKind::Force, "\\mathbf{x}_i", "xᵢ",
     "\\mathbf{x}_i = \\mathbf{p}_i - \\mathbf{x}", Frame::World, "m"},
    {"force", "force", "force", Stage::Forces, IndexKind::None, "\\mathbf{F}", "F",
     "\\mathbf{F} = \\sum_i \\mathbf{f}_i", Frame::World, "N"},
    {"force_with_gravity", "force", "force", Stage::Forces, IndexKind::None, "\\mathbf{F}", "F",
     "\\mathbf{F} = \\sum_i \\mathbf{f}_i + M\\,\\mathbf{g}", Frame::World, "N"},
    {"applied_torque", "applied_torque", "applied torque", Stage::Forces, IndexKind::Torque, "\\mathbf{q}_j", "qⱼ",
     "\\mathbf{q}_j", Frame::World, "N·m"},
    {"torque_with_couples", "torque", "torque", Stage::Forces, IndexKind::None, "\\mathbf{q}", "q",
     "\\mathbf{q} = \\sum_i \\mathbf{x}_i \\times \\mathbf{f}_i + \\sum_j \\mathbf{q}_j",
     Frame::World, "N·m"},
    {"torque", "torque", "torque", Stage::Forces, IndexKind::None, "\\mathbf{q}", "q",
     "\\mathbf{q} = \\sum_i \\mathbf{x}_i \\times \\mathbf{f}_i", Frame::World, "N·m"},
    // --- integration stage (explicit Euler, algorithm steps 2-7) ---
    {"position", "position", "position", Stage::Integration, IndexKind::None, "\\mathbf{x}", "x",
     "\\mathbf{x} \\leftarrow \\mathbf{x} + h\\,\\mathbf{v}", Frame::World, "m"},
    {"linear_velocity", "linear_velocity", "linear velocity", Stage::Integration, IndexKind::None, "\\mathbf{v}", "v",
     "\\mathbf{v} \\leftarrow \\mathbf{v} + h\\,\\mathbf{F}/M", Frame::World, "m/s"},
    {"orientation", "orientation", "orientation", Stage::Integration, IndexKind::None, "r", "r",
     "r \\leftarrow \\frac{r + \\frac{h}{2}\\,(0,\\boldsymbol{\\omega})\\,r}{\\lVert r + \\frac{h}{2}\\,(0,\\boldsymbol{\\omega})\\,r \\rVert}",
     Frame::World, ""},
    {"orientation_norm", "orientation_norm", "orientation norm", Stage::Integration, IndexKind::None, "\\lVert\\cdot\\rVert", "‖r*‖",
     "\\lVert r + \\tfrac{h}{2}\\,(0,\\boldsymbol{\\omega})\\,r \\rVert\\ \\text{(before normalising)}", Frame::None, ""},
    {"angular_momentum", "angular_momentum", "angular momentum", Stage::Integration, IndexKind::None, "\\mathbf{L}", "L",
     "\\mathbf{L} \\leftarrow \\mathbf{L} + h\\,\\mathbf{q}", Frame::World, "kg·m²/s"},
    {"inertia_body", "inertia_body", "inertia body", Stage::Integration, IndexKind::None, "I_0", "I₀",
     "I_0 = \\tfrac{M}{12}\\operatorname{diag}(b^2+c^2,\\ a^2+c^2,\\ a^2+b^2)", Frame::Body, "kg·m²"},
    {"inverse_inertia_body", "inverse_inertia_body", "inverse inertia body", Stage::Integration, IndexKind::None, "I_0^{-1}", "I₀⁻¹",
     "I_0^{-1} = \\operatorname{diag}(1/I_{0,xx},\\ 1/I_{0,yy},\\ 1/I_{0,zz})",
     Frame::Body, "1/(kg·m²)"},
    {"rotation_matrix", "rotation_matrix", "rotation matrix", Stage::Integration, IndexKind::None, "R", "R",
     "R = R(r)", Frame::World, ""},
    {"inverse_inertia_world", "inverse_inertia_world", "inverse inertia world", Stage::Integration, IndexKind::None, "I^{-1}", "I⁻¹",
     "I^{-1} = R\\,I_0^{-1}\\,R^{\\mathsf{T}}", Frame::World, "1/(kg·m²)"},
    {"inverse_inertia_world_template", "inverse_inertia_world", "inverse inertia world", Stage::Integration, IndexKind::None, "I^{-1}", "I⁻¹",
     "I^{-1} = R^{\\mathsf{T}}\\,I_0^{-1}\\,R", Frame::World, "1/(kg·m²)"},
    {"angular_velocity", "angular_velocity", "angular velocity", Stage::Integration, IndexKind::None, "\\boldsymbol{\\omega}", "ω",
     "\\boldsymbol{\\omega} = I^{-1}\\,\\mathbf{L}", Frame::World, "rad/s"},
    // --- probes (algorithm step 8) ---
    {"p_B", "p_B", "point in the body frame", Stage::Probes, IndexKind::Probe, "\\mathbf{p}_B", "p_B",
     "\\mathbf{p}_B\\ \\text{(the point fixed in the body, from the scene)}", Frame::Body, "m"},
    {"probe_position", "probe_position", "probe position", Stage::Probes, IndexKind::Probe, "\\mathbf{p}", "p",
     "\\mathbf{p} = \\mathbf{x} + R\\,\\mathbf{p}_B", Frame::World, "m"},
    {"point_velocity", "point_velocity", "point velocity", Stage::Probes, IndexKind::Probe, "\\mathbf{v}_p", "v_p",
     "\\mathbf{v}_p = \\mathbf{v} + \\boldsymbol{\\omega} \\times (\\mathbf{p} - \\mathbf{x})",
     Frame::World, "m/s"},
    {"omega_cross_r_W", "omega_cross_r_W", "rotational point velocity", Stage::Probes, IndexKind::Probe,
     "\\boldsymbol{\\omega}\\times(\\mathbf{p} - \\mathbf{x})", "ω×(p−x)",
     "\\boldsymbol{\\omega}\\times(\\mathbf{p} - \\mathbf{x})\\ \\text{(the rotation's share of}\\ \\mathbf{v}_p)", Frame::World, "m/s"},
    // --- collision stage (docs/references.md §2–§3) ---
    // World-level broad-phase counts (body -1).
    {"pairs_tested", "pairs_tested", "pairs tested", Stage::Collision, IndexKind::None, "N_{\\text{tested}}", "N",
     "\\text{AABB pairs tested by sweep-and-prune}", Frame::None, ""},
    {"pairs_overlapping", "pairs_overlapping", "pairs overlapping", Stage::Collision, IndexKind::None, "N_{\\text{overlap}}", "N",
     "\\text{AABB pairs that overlap (sent to SAT)}", Frame::None, ""},
    // Per contact (index = contact number).
    {"contact_point", "point", "contact point", Stage::Collision, IndexKind::Contact, "\\mathbf{p}", "p",
     "\\mathbf{p}\\ \\text{(contact point)}", Frame::World, "m"},
    {"contact_normal", "normal", "normal", Stage::Collision, IndexKind::Contact, "\\mathbf{n}", "n",
     "\\mathbf{n}\\ \\text{(unit, from B to A)}", Frame::World, ""},
    {"contact_depth", "depth", "depth", Stage::Collision, IndexKind::Contact, "d", "d",
     "d\\ \\text{(penetration, not used by } J)", Frame::None, "m"},
    {"x_a", "x_a", "x_a", Stage::Collision, IndexKind::Contact, "\\mathbf{x}_a", "x_a",
     "\\mathbf{x}_a = \\mathbf{p} - \\mathbf{x}_A", Frame::World, "m"},
    {"x_b", "x_b", "x_b", Stage::Collision, IndexKind::Contact, "\\mathbf{x}_b", "x_b",
     "\\mathbf{x}_b = \\mathbf{p} - \\mathbf{x}_B", Frame::World, "m"},
    {"velocity_a", "velocity_a", "velocity A", Stage::Collision, IndexKind::Contact, "\\mathbf{v}_A(\\mathbf{p})", "v_A(p)",
     "\\mathbf{v}_A(\\mathbf{p}) = \\mathbf{v}_A + \\boldsymbol{\\omega}_A \\times \\mathbf{x}_a",
     Frame::World, "m/s"},
    {"velocity_b", "velocity_b", "velocity B", Stage::Collision, IndexKind::Contact, "\\mathbf{v}_B(\\mathbf{p})", "v_B(p)",
     "\\mathbf{v}_B(\\mathbf{p}) = \\mathbf{v}_B + \\boldsymbol{\\omega}_B \\times \\mathbf{x}_b",
     Frame::World, "m/s"},
    {"relative_velocity", "relative_velocity", "relative velocity", Stage::Collision, IndexKind::Contact, "\\mathbf{v}_{\\text{rel}}", "v_rel",
     "\\mathbf{v}_{\\text{rel}} = \\mathbf{v}_A(\\mathbf{p}) - \\mathbf{v}_B(\\mathbf{p})",
     Frame::World, "m/s"},
    {"normal_velocity", "normal_velocity", "normal velocity", Stage::Collision, IndexKind::Contact, "\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}", "v_rel·n",
     "\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}\\ (> 0:\\ \\text{separating, no impulse})",
     Frame::None, "m/s"},
    {"restitution", "restitution", "restitution", Stage::Collision, IndexKind::Contact, "c", "c",
     "c\\ \\text{(coefficient of restitution)}", Frame::None, ""},
    {"numerator", "numerator", "numerator", Stage::Collision, IndexKind::Contact, "-(1+c)\\,\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}", "−(1+c) v_rel·n",
     "-(1+c)\\,\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}",
     Frame::None, "m/s"},
    {"inv_mass_a", "inv_mass_a", "inverse mass A", Stage::Collision, IndexKind::Contact, "1/M_A", "1/M_A",
     "1/M_A", Frame::None, "1/kg"},
    {"inv_mass_b", "inv_mass_b", "inverse mass B", Stage::Collision, IndexKind::Contact, "1/M_B", "1/M_B",
     "1/M_B\\ (0\\ \\text{if fixed})", Frame::None, "1/kg"},
    {"rotational_a", "rotational_a", "rotational A", Stage::Collision, IndexKind::Contact, "[\\cdot]_A", "[(I_A⁻¹(x_a×n))×x_a]·n",
     "\\big[(I_A^{-1}(\\mathbf{x}_a\\times\\mathbf{n}))\\times\\mathbf{x}_a\\big]\\cdot\\mathbf{n}",
     Frame::None, "1/kg"},
    {"rotational_b", "rotational_b", "rotational B", Stage::Collision, IndexKind::Contact, "[\\cdot]_B", "[(I_B⁻¹(x_b×n))×x_b]·n",
     "\\big[(I_B^{-1}(\\mathbf{x}_b\\times\\mathbf{n}))\\times\\mathbf{x}_b\\big]\\cdot\\mathbf{n}",
     Frame::None, "1/kg"},
    {"denominator", "denominator", "denominator", Stage::Collision, IndexKind::Contact, "k_n", "1/M_A + 1/M_B + [·]_A + [·]_B",
     "\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_A + [\\cdot]_B",
     Frame::None, "1/kg"},
    {"impulse", "impulse", "impulse", Stage::Collision, IndexKind::Contact, "J", "J",
     "J = \\frac{-(1+c)\\,\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}}{\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_A + [\\cdot]_B}",
     Frame::None, "N·s"},
    {"friction_impulse", "friction_impulse", "friction impulse", Stage::Collision, IndexKind::Contact, "J_t\\,\\mathbf{t}", "J_t t",
     "J_t = \\min\\!\\Big(\\frac{|\\mathbf{v}_{\\text{rel},t}|}{\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_{A,t} + [\\cdot]_{B,t}},\\ \\mu J\\Big)",
     Frame::World, "N·s"},
    {"tangent_speed", "tangent_speed", "tangent speed", Stage::Collision, IndexKind::Contact, "|\\mathbf{v}_{\\text{rel},t}|", "|v_rel,t|",
     "|\\mathbf{v}_{\\text{rel},t}| = |\\mathbf{v}_{\\text{rel}} - (\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n})\\,\\mathbf{n}|\\ \\text{(after the normal impulse)}", Frame::None, "m/s"},
    {"friction_direction", "friction_direction", "friction direction", Stage::Collision, IndexKind::Contact, "\\mathbf{t}", "t",
     "\\mathbf{t} = -\\mathbf{v}_{\\text{rel},t}/|\\mathbf{v}_{\\text{rel},t}|\\ \\text{(against the sliding)}", Frame::World, ""},
    {"tangent_denominator", "tangent_denominator", "tangent denominator", Stage::Collision, IndexKind::Contact, "k_t", "k_t",
     "k_t = \\tfrac{1}{M_A} + \\tfrac{1}{M_B} + [\\cdot]_{A,t} + [\\cdot]_{B,t}", Frame::None, "1/kg"},
    {"friction_coefficient", "friction_coefficient", "friction coefficient", Stage::Collision, IndexKind::Contact, "\\mu", "μ",
     "\\mu\\ \\text{(Coulomb friction coefficient)}", Frame::None, ""},
    {"sliding", "sliding", "sliding", Stage::Collision, IndexKind::Contact, "s", "sliding",
     "s = 1\\ \\text{if}\\ J_t^{*} > \\mu J\\ \\text{(slides, } J_t = \\mu J),\\ 0\\ \\text{if it sticks}",
     Frame::None, ""},
    {"delta_v_a", "delta_v_a", "delta v A", Stage::Collision, IndexKind::Contact, "\\Delta\\mathbf{v}_A", "Δv_A",
     "\\Delta\\mathbf{v}_A = (J\\,\\mathbf{n} + J_t\\mathbf{t})/M_A", Frame::World, "m/s"},
    {"delta_v_b", "delta_v_b", "delta v B", Stage::Collision, IndexKind::Contact, "\\Delta\\mathbf{v}_B", "Δv_B",
     "\\Delta\\mathbf{v}_B = -(J\\,\\mathbf{n} + J_t\\mathbf{t})/M_B", Frame::World, "m/s"},
    {"delta_L_a", "delta_L_a", "delta L A", Stage::Collision, IndexKind::Contact, "\\Delta\\mathbf{L}_A", "ΔL_A",
     "\\Delta\\mathbf{L}_A = \\mathbf{x}_a \\times (J\\,\\mathbf{n} + J_t\\mathbf{t})",
     Frame::World, "kg·m²/s"},
    {"delta_L_b", "delta_L_b", "delta L B", Stage::Collision, IndexKind::Contact, "\\Delta\\mathbf{L}_B", "ΔL_B",
     "\\Delta\\mathbf{L}_B = -\\mathbf{x}_b \\times (J\\,\\mathbf{n} + J_t\\mathbf{t})",
     Frame::World, "kg·m²/s"},
    {"linear_velocity_a", "linear_velocity_a", "linear velocity A", Stage::Collision, IndexKind::Contact, "\\mathbf{v}_A'", "v_A'",
     "\\mathbf{v}_A' = \\mathbf{v}_A + \\Delta\\mathbf{v}_A", Frame::World, "m/s"},
    {"linear_velocity_b", "linear_velocity_b", "linear velocity B", Stage::Collision, IndexKind::Contact, "\\mathbf{v}_B'", "v_B'",
     "\\mathbf{v}_B' = \\mathbf{v}_B + \\Delta\\mathbf{v}_B", Frame::World, "m/s"},
    {"angular_momentum_a", "angular_momentum_a", "angular momentum A", Stage::Collision, IndexKind::Contact, "\\mathbf{L}_A'", "L_A'",
     "\\mathbf{L}_A' = \\mathbf{L}_A + \\Delta\\mathbf{L}_A",
     Frame::World, "kg·m²/s"},
    {"angular_momentum_b", "angular_momentum_b", "angular momentum B", Stage::Collision, IndexKind::Contact, "\\mathbf{L}_B'", "L_B'",
     "\\mathbf{L}_B' = \\mathbf{L}_B + \\Delta\\mathbf{L}_B",
     Frame::World, "kg·m²/s"},
    {"angular_velocity_a", "angular_velocity_a", "angular velocity A", Stage::Collision, IndexKind::Contact, "\\boldsymbol{\\omega}_A'", "ω_A'",
     "\\boldsymbol{\\omega}_A' = I_A^{-1}\\,\\mathbf{L}_A'",
     Frame::World, "rad/s"},
    {"angular_velocity_b", "angular_velocity_b", "angular velocity B", Stage::Collision, IndexKind::Contact, "\\boldsymbol{\\omega}_B'", "ω_B'",
     "\\boldsymbol{\\omega}_B' = I_B^{-1}\\,\\mathbf{L}_B'",
     Frame::World, "rad/s"},
    {"kinetic_energy_before", "kinetic_energy_before", "kinetic energy before", Stage::Collision, IndexKind::Contact, "T", "T",
     "T = \\sum_{A,B} \\tfrac12 M|\\mathbf{v}|^2 + \\tfrac12\\boldsymbol{\\omega}\\cdot\\mathbf{L}",
     Frame::None, "J"},
    {"kinetic_energy_after", "kinetic_energy_after", "kinetic energy after", Stage::Collision, IndexKind::Contact, "T'", "T'",
     "T' = \\sum_{A,B} \\tfrac12 M|\\mathbf{v}'|^2 + \\tfrac12\\boldsymbol{\\omega}'\\cdot\\mathbf{L}'",
     Frame::None, "J"},
    // --- correction stage: not part of the impulse formula ---
    {"correction_depth", "correction_depth", "correction depth", Stage::Correction, IndexKind::Correction, "d", "d",
     "d\\ \\text{(the overlap this correction removes)}", Frame::None, "m"},
    {"correction_normal", "correction_normal", "correction normal", Stage::Correction, IndexKind::Correction, "\\mathbf{n}", "n",
     "\\mathbf{n}\\ \\text{(unit, from B to A)}", Frame::World, ""},
    {"correction_inv_mass_a", "correction_inv_mass_a", "correction inverse mass A", Stage::Correction, IndexKind::Correction, "1/M_A", "1/M_A",
     "1/M_A", Frame::None, "1/kg"},
    {"correction_inv_mass_b", "correction_inv_mass_b", "correction inverse mass B", Stage::Correction, IndexKind::Correction, "1/M_B", "1/M_B",
     "1/M_B\\ (0\\ \\text{for a plane or a fixed body})", Frame::None, "1/kg"},
    {"correction_a", "correction_a", "correction A", Stage::Correction, IndexKind::Correction, "\\Delta\\mathbf{x}_A", "Δx_A",
     "\\Delta\\mathbf{x}_A = d\\,\\mathbf{n}\\,\\frac{1/M_A}{1/M_A + 1/M_B}",
     Frame::World, "m"},
    {"correction_b", "correction_b", "correction B", Stage::Correction, IndexKind::Correction, "\\Delta\\mathbf{x}_B", "Δx_B",
     "\\Delta\\mathbf{x}_B = -d\\,\\mathbf{n}\\,\\frac{1/M_B}{1/M_A + 1/M_B}",
     Frame::World, "m"},
    // --- manifold contact model (contact_model "manifold"; physics/engine/manifold/, docs/collisions.md;
    //     Catto GDC 2005/2006/2009, Box2D-lite, Ericson; docs/references.md) ---
    // World-level counts (body -1).
    {"manifold_points", "manifold_points", "manifold points", Stage::Collision, IndexKind::None, "N_{\\text{points}}", "N_points",
     "\\text{manifold points this step (at most 8 per box pair or box and plane)}", Frame::None, ""},
    {"solver_iterations_used", "solver_iterations", "solver iterations", Stage::Collision, IndexKind::None, "n_{\\text{iter}}", "n_iter",
     "n_{\\text{iter}}:\\ \\text{velocity iterations until}\\ \\max|\\Delta\\lambda| \\le \\varepsilon\\ \\text{(at most solver\\_iterations)}",
     Frame::None, ""},
    // Per manifold point (index = contact number; one ContactHeader per point).
    {"manifold_point", "point", "contact point", Stage::Collision, IndexKind::Contact, "\\mathbf{p}", "p",
     "\\mathbf{p} = \\tfrac12(\\mathbf{p}_A + \\mathbf{p}_B)\\ \\text{(clipped manifold point)}", Frame::World, "m"},
    {"manifold_normal", "normal", "normal", Stage::Collision, IndexKind::Contact, "\\mathbf{n}", "n",
     "\\mathbf{n}\\ \\text{(reference face normal, unit, from B to A)}", Frame::World, ""},
    {"manifold_depth", "depth", "depth", Stage::Collision, IndexKind::Contact, "d", "d",
     "d = -\\mathbf{n}\\cdot(\\mathbf{p}_A - \\mathbf{p}_B)\\ \\ (d < 0:\\ \\text{apart, a speculative point})",
     Frame::None, "m"},
    {"feature_id", "feature_id", "feature id", Stage::Collision, IndexKind::Contact, "\\text{id}", "id",
     "\\text{feature id (reference face, incident face, clip lines; a corner for planes): the warm-start key}",
     Frame::None, ""},
    {"manifold_normal_velocity", "normal_velocity", "normal velocity", Stage::Collision, IndexKind::Contact,
     "\\mathbf{v}_{\\text{rel}}\\cdot\\mathbf{n}", "v_rel·n",
     "v_n = \\big(\\mathbf{v}_A + \\boldsymbol{\\omega}_A\\times\\mathbf{r}_A - \\mathbf{v}_B - \\boldsymbol{\\omega}_B\\times\\mathbf{r}_B\\big)\\cdot\\mathbf{n}\\ \\text{(start of step)}",
     Frame::None, "m/s"},
    {"target_normal_velocity", "target_normal_velocity", "target normal velocity", Stage::Collision, IndexKind::Contact, "v_n^{*}", "v_n*",
     "v_n^{*} = -c\\,v_n\\ \\text{if}\\ v_n < -v_{\\text{th}};\\ \\ -d/h\\ \\text{if apart};\\ \\ 0\\ \\text{otherwise}",
     Frame::None, "m/s"},
    {"target_normal_velocity_baumgarte", "target_normal_velocity", "target normal velocity", Stage::Collision, IndexKind::Contact, "v_n^{*}", "v_n*",
     "v_n^{*} = \\max\\!\\big(v_{\\text{bounce}},\\ \\tfrac{\\beta}{h}\\max(0,\\ d - \\text{slop})\\big)\\ \\text{(Baumgarte)}",
     Frame::None, "m/s"},
    {"r_A_W", "r_A_W", "lever arm A", Stage::Collision, IndexKind::Contact, "\\mathbf{r}_A", "r_A",
     "\\mathbf{r}_A = \\mathbf{p} - \\mathbf{x}_A", Frame::World, "m"},
    {"r_B_W", "r_B_W", "lever arm B", Stage::Collision, IndexKind::Contact, "\\mathbf{r}_B", "r_B",
     "\\mathbf{r}_B = \\mathbf{p} - \\mathbf{x}_B", Frame::World, "m"},
    {"manifold_rotational_a", "rotational_a", "rotational A", Stage::Collision, IndexKind::Contact, "[\\cdot]_A", "(r_A×n)·I_A⁻¹(r_A×n)",
     "(\\mathbf{r}_A\\times\\mathbf{n})\\cdot I_A^{-1}(\\mathbf{r}_A\\times\\mathbf{n}) = \\big[(I_A^{-1}(\\mathbf{r}_A\\times\\mathbf{n}))\\times\\mathbf{r}_A\\big]\\cdot\\mathbf{n}",
     Frame::None, "1/kg"},
    {"manifold_rotational_b", "rotational_b", "rotational B", Stage::Collision, IndexKind::Contact, "[\\cdot]_B", "(r_B×n)·I_B⁻¹(r_B×n)",
     "(\\mathbf{r}_B\\times\\mathbf{n})\\cdot I_B^{-1}(\\mathbf{r}_B\\times\\mathbf{n})\\ (0\\ \\text{for a plane})",
     Frame::None, "1/kg"},
    {"gap_rate", "gap_rate", "gap rate", Stage::Collision, IndexKind::Contact, "d/h", "d/h",
     "d/h\\ \\text{(the overlap per step; } < 0 \\text{ apart; no bounce: } v_n^{*} = \\min(0,\\ d/h))", Frame::None, "m/s"},
    {"normal_mass", "normal_mass", "normal mass", Stage::Collision, IndexKind::Contact, "m_n", "m_n",
     "m_n = \\Big(\\tfrac{1}{M_A} + \\tfrac{1}{M_B} + \\big[(I_A^{-1}(\\mathbf{r}_A\\times\\mathbf{n}))\\times\\mathbf{r}_A + (I_B^{-1}(\\mathbf{r}_B\\times\\mathbf{n}))\\times\\mathbf{r}_B\\big]\\cdot\\mathbf{n}\\Big)^{-1}",
     Frame::None, "kg"},
    {"warm_start_normal", "warm_start_normal", "warm start normal", Stage::Collision, IndexKind::Contact, "\\lambda_n^{0}", "λn⁰",
     "\\lambda_n^{0} = \\lambda_n\\ \\text{of last step's point with the same feature id (0 if none)}",
     Frame::None, "N·s"},
    {"warm_start_tangent", "warm_start_tangent", "warm start tangent", Stage::Collision, IndexKind::Contact, "\\boldsymbol{\\lambda}_t^{0}", "λt⁰",
     "\\boldsymbol{\\lambda}_t^{0} = \\boldsymbol{\\lambda}_t\\ \\text{of last step's point, projected on this step's tangent plane}",
     Frame::World, "N·s"},
    {"normal_impulse", "normal_impulse", "normal impulse", Stage::Collision, IndexKind::Contact, "\\lambda_n", "λn",
     "\\lambda_n \\leftarrow \\max\\!\\big(0,\\ \\lambda_n + m_n(v_n^{*} - v_n)\\big)\\ \\text{(accumulated over the iterations)}",
     Frame::None, "N·s"},
    {"tangent_impulse", "tangent_impulse", "tangent impulse", Stage::Collision, IndexKind::Contact, "\\boldsymbol{\\lambda}_t", "λt",
     "\\boldsymbol{\\lambda}_t \\leftarrow \\boldsymbol{\\lambda}_t - m_t\\mathbf{v}_t,\\ \\text{then scaled to}\\ |\\boldsymbol{\\lambda}_t| \\le \\mu\\lambda_n\\ \\text{(accumulated)}",
     Frame::World, "N·s"},
    // The soft step (solver "soft-step"; soft_step_solver.h, Box2D v3 / Solver2D): world-level
    // numbers of the step, then per point, then per body.
    {"soft_substep", "substep_length", "substep length", Stage::Collision, IndexKind::None, "h_s", "h_s",
     "h_s = h / n_{\\text{sub}}", Frame::None, "s"},
    {"soft_contact_hertz", "contact_hertz", "contact hertz", Stage::Collision, IndexKind::None, "f", "f",
     "f = \\tfrac{1}{8 h_s}\\ \\text{(twice that against a fixed body or a plane)}", Frame::None, "Hz"},
    {"soft_bias_rate", "bias_rate", "bias rate", Stage::Collision, IndexKind::None, "\\beta_s", "β_s",
     "\\beta_s = \\frac{\\omega}{2\\zeta + h_s\\omega},\\ \\omega = 2\\pi f", Frame::None, "1/s"},
    {"soft_mass_scale", "mass_scale", "mass scale", Stage::Collision, IndexKind::None, "s_m", "s_m",
     "s_m = \\frac{a}{1 + a},\\ a = h_s\\omega\\,(2\\zeta + h_s\\omega)", Frame::None, ""},
    {"soft_impulse_scale", "impulse_scale", "impulse scale", Stage::Collision, IndexKind::None, "s_i", "s_i",
     "s_i = \\frac{1}{1 + a} = 1 - s_m", Frame::None, ""},
    {"soft_normal_impulse", "normal_impulse", "normal impulse", Stage::Collision, IndexKind::Contact, "\\lambda_n", "λn",
     "\\lambda_n \\leftarrow \\max\\!\\big(0,\\ \\lambda_n - m_n s_m (v_n + \\max(\\beta_s s,\\ -v_{\\text{push}})) - s_i\\lambda_n\\big)\\ \\text{(last substep, after its relax)}",
     Frame::None, "N·s"},
    {"step_normal_impulse", "step_normal_impulse", "step normal impulse", Stage::Collision, IndexKind::Contact, "P_n", "P_n",
     "P_n = \\sum_{\\text{substeps}} \\lambda_n + \\Delta\\lambda_{\\text{bounce}}\\ \\text{(the step's normal impulse)}",
     Frame::None, "N·s"},
    {"soft_push_out", "push_out", "push out", Stage::Correction, IndexKind::None, "\\Delta\\mathbf{x}_s", "Δx_s",
     "\\Delta\\mathbf{x}_s = \\sum_{\\text{substeps}} h_s\\mathbf{v}_i - h\\,\\mathbf{v}_{n+1}\\ \\text{(what the substeps moved beyond the final velocity)}",
     Frame::World, "m"},
    // Per body (index -1).
    {"contact_impulse_sum", "contact_impulse_sum", "contact impulse sum", Stage::Collision, IndexKind::None, "\\sum\\mathbf{P}", "ΣP",
     "\\sum\\mathbf{P}\\ \\text{(the solver's impulses on the body in this step)}", Frame::World, "N·s"},
    {"contact_moment_sum", "contact_moment_sum", "contact moment sum", Stage::Collision, IndexKind::None, "\\sum\\mathbf{r}\\times\\mathbf{P}", "Σr×P",
     "\\sum\\mathbf{r}\\times\\mathbf{P}\\ \\text{(their moments about the centre of mass)}", Frame::World, "kg·m²/s"},
    {"contact_force", "contact_force", "contact force", Stage::Collision, IndexKind::None, "\\mathbf{F}_c", "F_c",
     "\\mathbf{F}_c = \\tfrac1h\\sum \\mathbf{P}\\ \\text{(the solver's impulses on the body, added to}\\ \\mathbf{F})",
     Frame::World, "N"},
    {"contact_torque", "contact_torque", "contact torque", Stage::Collision, IndexKind::None, "\\mathbf{q}_c", "q_c",
     "\\mathbf{q}_c = \\tfrac1h\\sum \\mathbf{r}\\times\\mathbf{P}\\ \\text{(added to}\\ \\mathbf{q})",
     Frame::World, "N·m"},
    {"sleep_contact_force", "contact_force", "contact force", Stage::Collision, IndexKind::None, "\\mathbf{F}_c", "F_c",
     "\\mathbf{F}_c = -\\mathbf{F}\\ \\text{(asleep: the support holds the body still)}", Frame::World, "N"},
    {"sleep_contact_torque", "contact_torque", "contact torque", Stage::Collision, IndexKind::None, "\\mathbf{q}_c", "q_c",
     "\\mathbf{q}_c = -\\mathbf{q}\\ \\text{(asleep)}", Frame::World, "N·m"},
    // The manifold model's velocity update (manifold_velocity_stage.h), before the integration.
    {"solved_linear_velocity", "solved_linear_velocity", "solved linear velocity", Stage::Integration, IndexKind::None, "\\mathbf{v}_{n+1}", "v⁺",
     "\\mathbf{v}_{n+1} = \\mathbf{v}_n + h\\,(\\mathbf{F} + \\mathbf{F}_c)/M", Frame::World, "m/s"},
    {"solved_angular_momentum", "solved_angular_momentum", "solved angular momentum", Stage::Integration, IndexKind::None, "\\mathbf{L}_{n+1}", "L⁺",
     "\\mathbf{L}_{n+1} = \\mathbf{L}_n + h\\,(\\mathbf{q} + \\mathbf{q}_c)", Frame::World, "kg·m²/s"},
    {"solved_angular_velocity", "solved_angular_velocity", "solved angular velocity", Stage::Integration, IndexKind::None, "\\boldsymbol{\\omega}_{n+1}", "ω⁺",
     "\\boldsymbol{\\omega}_{n+1} = I^{-1}(\\mathbf{r}_n)\\,\\mathbf{L}_{n+1}", Frame::World, "rad/s"},
    {"sleep_time", "sleep_time", "sleep time", Stage::Correction, IndexKind::None, "t_{\\text{rest}}", "t_rest",
     "t_{\\text{rest}} \\leftarrow t_{\\text{rest}} + h\\ \\text{if}\\ |\\mathbf{v}| \\le v_{\\text{sleep}}\\ \\text{and}\\ |\\boldsymbol{\\omega}| \\le \\omega_{\\text{sleep}},\\ \\text{else}\\ 0",
     Frame::None, "s"},
    {"asleep", "asleep", "asleep", Stage::Correction, IndexKind::None, "s", "asleep",
     "s = 1\\ \\text{if the body's island rested}\\ t_{\\text{rest}} \\ge t_{\\text{sleep}}\\ \\text{(}\\mathbf{v} = \\mathbf{L} = 0\\text{)},\\ 0\\ \\text{awake}",
     Frame::None, ""},
    // Position fix (non-linear Gauss-Seidel), per body and world-level.
    {"ngs_correction", "correction_a", "correction A", Stage::Correction, IndexKind::Correction, "\\Delta\\mathbf{x}_A", "Δx_A",
     "\\Delta\\mathbf{x}_A = \\sum \\tfrac{1}{M_A}P\\,\\mathbf{n},\\ P = -C/K,\\ C = \\operatorname{clamp}(\\beta(s + \\text{slop}),\\ -C_{\\max},\\ 0)\\ \\text{(NGS)}",
     Frame::World, "m"},
    {"deepest_overlap", "deepest_overlap", "deepest overlap", Stage::Correction, IndexKind::None, "d_{\\max}", "d_max",
     "d_{\\max} = \\max\\big(0,\\ \\max_{\\text{points}} -s\\big)\\ \\text{after the position fix}", Frame::None, "m"},
};
// clang-format on

namespace detail {
template <std::size_t A, std::size_t B>
consteval std::array<QuantityInfo, A + B> joinRows(const QuantityInfo (&a)[A], const QuantityInfo (&b)[B])
{
    std::array<QuantityInfo, A + B> out{};
    for (std::size_t i = 0; i < A; ++i) out[i] = a[i];
    for (std::size_t i = 0; i < B; ++i) out[A + i] = b[i];
    return out;
}
} // namespace detail

// The one table: the engine's rows, then the integrators' rows.
inline constexpr std::array kQuantityCatalogue = detail::joinRows(kEngineQuantityRows, kIntegratorQuantityRows);

// Every row of the catalogue, in table order.
constexpr std::span<const QuantityInfo> quantityCatalogue() { return kQuantityCatalogue; }

// The first row with this trace id (the rows of one id share symbol, frame and unit);
// nullptr for an id that is not in the catalogue.
const QuantityInfo* findQuantity(std::string_view id);
inline bool isQuantityId(std::string_view id) { return findQuantity(id) != nullptr; }

namespace detail {

// The row with this key, at compile time: a key that is not in the table does not compile.
consteval const QuantityInfo& catalogueEntry(std::string_view key)
{
    for (const QuantityInfo& q : kQuantityCatalogue) {
        if (std::string_view(q.key) == key) return q;
    }
    throw "quantity key not in the catalogue";
}

consteval bool catalogueKeysUnique()
{
    // Each key measured once, then the pairs compared (mostly by length): an strlen per
    // pair went past clang's constexpr step limit once the catalogue grew.
    std::array<std::string_view, std::size(kQuantityCatalogue)> keys{};
    for (size_t i = 0; i < keys.size(); ++i) keys[i] = kQuantityCatalogue[i].key;
    for (size_t i = 0; i < keys.size(); ++i) {
        for (size_t j = i + 1; j < keys.size(); ++j) {
            if (keys[i] == keys[j]) return false;
        }
    }
    return true;
}
static_assert(catalogueKeysUnique(), "every catalogue row needs its own key");

} // namespace detail
} // namespace rbw
