// Named handles into the quantity catalogue (quantity_catalogue.h), for the physics
// statements that record a value: `record(trace, q::position, b, s.x_W)`. Each handle
// is a reference to one row, found by its key at compile time.
#pragma once

#include "physics/quantity_catalogue.h"

namespace rbw::q {

inline constexpr const QuantityInfo& gravity_force = detail::catalogueEntry("gravity_force");
inline constexpr const QuantityInfo& applied_force = detail::catalogueEntry("applied_force");
inline constexpr const QuantityInfo& application_point = detail::catalogueEntry("application_point");
inline constexpr const QuantityInfo& lever_arm = detail::catalogueEntry("lever_arm");
inline constexpr const QuantityInfo& force = detail::catalogueEntry("force");
inline constexpr const QuantityInfo& force_with_gravity = detail::catalogueEntry("force_with_gravity");
inline constexpr const QuantityInfo& applied_torque = detail::catalogueEntry("applied_torque");
inline constexpr const QuantityInfo& torque_with_couples = detail::catalogueEntry("torque_with_couples");
inline constexpr const QuantityInfo& torque = detail::catalogueEntry("torque");
inline constexpr const QuantityInfo& position = detail::catalogueEntry("position");
inline constexpr const QuantityInfo& linear_velocity = detail::catalogueEntry("linear_velocity");
inline constexpr const QuantityInfo& orientation = detail::catalogueEntry("orientation");
inline constexpr const QuantityInfo& angular_momentum = detail::catalogueEntry("angular_momentum");
inline constexpr const QuantityInfo& inertia_body = detail::catalogueEntry("inertia_body");
inline constexpr const QuantityInfo& inverse_inertia_body = detail::catalogueEntry("inverse_inertia_body");
inline constexpr const QuantityInfo& rotation_matrix = detail::catalogueEntry("rotation_matrix");
inline constexpr const QuantityInfo& inverse_inertia_world = detail::catalogueEntry("inverse_inertia_world");
inline constexpr const QuantityInfo& inverse_inertia_world_template = detail::catalogueEntry("inverse_inertia_world_template");
inline constexpr const QuantityInfo& angular_velocity = detail::catalogueEntry("angular_velocity");
inline constexpr const QuantityInfo& probe_position = detail::catalogueEntry("probe_position");
inline constexpr const QuantityInfo& point_velocity = detail::catalogueEntry("point_velocity");
inline constexpr const QuantityInfo& pairs_tested = detail::catalogueEntry("pairs_tested");
inline constexpr const QuantityInfo& pairs_overlapping = detail::catalogueEntry("pairs_overlapping");
inline constexpr const QuantityInfo& contact_point = detail::catalogueEntry("contact_point");
inline constexpr const QuantityInfo& contact_normal = detail::catalogueEntry("contact_normal");
inline constexpr const QuantityInfo& contact_depth = detail::catalogueEntry("contact_depth");
inline constexpr const QuantityInfo& x_a = detail::catalogueEntry("x_a");
inline constexpr const QuantityInfo& x_b = detail::catalogueEntry("x_b");
inline constexpr const QuantityInfo& velocity_a = detail::catalogueEntry("velocity_a");
inline constexpr const QuantityInfo& velocity_b = detail::catalogueEntry("velocity_b");
inline constexpr const QuantityInfo& relative_velocity = detail::catalogueEntry("relative_velocity");
inline constexpr const QuantityInfo& normal_velocity = detail::catalogueEntry("normal_velocity");
inline constexpr const QuantityInfo& restitution = detail::catalogueEntry("restitution");
inline constexpr const QuantityInfo& numerator = detail::catalogueEntry("numerator");
inline constexpr const QuantityInfo& inv_mass_a = detail::catalogueEntry("inv_mass_a");
inline constexpr const QuantityInfo& inv_mass_b = detail::catalogueEntry("inv_mass_b");
inline constexpr const QuantityInfo& rotational_a = detail::catalogueEntry("rotational_a");
inline constexpr const QuantityInfo& rotational_b = detail::catalogueEntry("rotational_b");
inline constexpr const QuantityInfo& denominator = detail::catalogueEntry("denominator");
inline constexpr const QuantityInfo& impulse = detail::catalogueEntry("impulse");
inline constexpr const QuantityInfo& friction_impulse = detail::catalogueEntry("friction_impulse");
inline constexpr const QuantityInfo& friction_coefficient = detail::catalogueEntry("friction_coefficient");
inline constexpr const QuantityInfo& sliding = detail::catalogueEntry("sliding");
inline constexpr const QuantityInfo& delta_v_a = detail::catalogueEntry("delta_v_a");
inline constexpr const QuantityInfo& delta_v_b = detail::catalogueEntry("delta_v_b");
inline constexpr const QuantityInfo& delta_L_a = detail::catalogueEntry("delta_L_a");
inline constexpr const QuantityInfo& delta_L_b = detail::catalogueEntry("delta_L_b");
inline constexpr const QuantityInfo& linear_velocity_a = detail::catalogueEntry("linear_velocity_a");
inline constexpr const QuantityInfo& linear_velocity_b = detail::catalogueEntry("linear_velocity_b");
inline constexpr const QuantityInfo& angular_momentum_a = detail::catalogueEntry("angular_momentum_a");
inline constexpr const QuantityInfo& angular_momentum_b = detail::catalogueEntry("angular_momentum_b");
inline constexpr const QuantityInfo& angular_velocity_a = detail::catalogueEntry("angular_velocity_a");
inline constexpr const QuantityInfo& angular_velocity_b = detail::catalogueEntry("angular_velocity_b");
inline constexpr const QuantityInfo& kinetic_energy_before = detail::catalogueEntry("kinetic_energy_before");
inline constexpr const QuantityInfo& kinetic_energy_after = detail::catalogueEntry("kinetic_energy_after");
inline constexpr const QuantityInfo& correction_a = detail::catalogueEntry("correction_a");
inline constexpr const QuantityInfo& correction_b = detail::catalogueEntry("correction_b");
inline constexpr const QuantityInfo& gyroscopic_skipped = detail::catalogueEntry("gyroscopic_skipped");
inline constexpr const QuantityInfo& se_linear_velocity = detail::catalogueEntry("se_linear_velocity");
inline constexpr const QuantityInfo& se_position = detail::catalogueEntry("se_position");
inline constexpr const QuantityInfo& se_angular_momentum = detail::catalogueEntry("se_angular_momentum");
inline constexpr const QuantityInfo& update_angular_velocity = detail::catalogueEntry("update_angular_velocity");
inline constexpr const QuantityInfo& se_orientation = detail::catalogueEntry("se_orientation");
inline constexpr const QuantityInfo& stage_velocity = detail::catalogueEntry("stage_velocity");
inline constexpr const QuantityInfo& stage_angular_velocity = detail::catalogueEntry("stage_angular_velocity");
inline constexpr const QuantityInfo& stage_orientation_rate = detail::catalogueEntry("stage_orientation_rate");
inline constexpr const QuantityInfo& stage_torque = detail::catalogueEntry("stage_torque");
inline constexpr const QuantityInfo& midpoint_position = detail::catalogueEntry("midpoint_position");
inline constexpr const QuantityInfo& midpoint_linear_velocity = detail::catalogueEntry("midpoint_linear_velocity");
inline constexpr const QuantityInfo& midpoint_orientation = detail::catalogueEntry("midpoint_orientation");
inline constexpr const QuantityInfo& midpoint_angular_momentum = detail::catalogueEntry("midpoint_angular_momentum");
inline constexpr const QuantityInfo& rk4_position = detail::catalogueEntry("rk4_position");
inline constexpr const QuantityInfo& rk4_linear_velocity = detail::catalogueEntry("rk4_linear_velocity");
inline constexpr const QuantityInfo& rk4_orientation = detail::catalogueEntry("rk4_orientation");
inline constexpr const QuantityInfo& rk4_angular_momentum = detail::catalogueEntry("rk4_angular_momentum");
inline constexpr const QuantityInfo& body_angular_velocity = detail::catalogueEntry("body_angular_velocity");
inline constexpr const QuantityInfo& gyroscopic_jacobian = detail::catalogueEntry("gyroscopic_jacobian");
inline constexpr const QuantityInfo& body_angular_velocity_new = detail::catalogueEntry("body_angular_velocity_new");
inline constexpr const QuantityInfo& newton_iterations = detail::catalogueEntry("newton_iterations");
inline constexpr const QuantityInfo& gyroscopic_residual = detail::catalogueEntry("gyroscopic_residual");
inline constexpr const QuantityInfo& gyroscopic_angular_velocity = detail::catalogueEntry("gyroscopic_angular_velocity");
inline constexpr const QuantityInfo& gyroscopic_angular_momentum = detail::catalogueEntry("gyroscopic_angular_momentum");
inline constexpr const QuantityInfo& body_angular_momentum = detail::catalogueEntry("body_angular_momentum");
inline constexpr const QuantityInfo& body_angular_momentum_new = detail::catalogueEntry("body_angular_momentum_new");
inline constexpr const QuantityInfo& midpoint_body_angular_velocity = detail::catalogueEntry("midpoint_body_angular_velocity");
inline constexpr const QuantityInfo& midpoint_world_angular_velocity = detail::catalogueEntry("midpoint_world_angular_velocity");
inline constexpr const QuantityInfo& midpoint_newton_residual = detail::catalogueEntry("midpoint_newton_residual");
inline constexpr const QuantityInfo& fixed_point_iterations = detail::catalogueEntry("fixed_point_iterations");
inline constexpr const QuantityInfo& fixed_point_residual = detail::catalogueEntry("fixed_point_residual");
inline constexpr const QuantityInfo& cayley_rotation = detail::catalogueEntry("cayley_rotation");
inline constexpr const QuantityInfo& cayley_orientation = detail::catalogueEntry("cayley_orientation");
inline constexpr const QuantityInfo& cayley_world_orientation = detail::catalogueEntry("cayley_world_orientation");
inline constexpr const QuantityInfo& half_kick_angular_momentum = detail::catalogueEntry("half_kick_angular_momentum");
inline constexpr const QuantityInfo& verlet_position = detail::catalogueEntry("verlet_position");
inline constexpr const QuantityInfo& verlet_linear_velocity = detail::catalogueEntry("verlet_linear_velocity");
inline constexpr const QuantityInfo& rotation_matrix_update = detail::catalogueEntry("rotation_matrix_update");
inline constexpr const QuantityInfo& orthonormality_error_before = detail::catalogueEntry("orthonormality_error_before");
inline constexpr const QuantityInfo& polar_rotation_matrix = detail::catalogueEntry("polar_rotation_matrix");
inline constexpr const QuantityInfo& drifting_rotation_matrix = detail::catalogueEntry("drifting_rotation_matrix");
inline constexpr const QuantityInfo& orthonormality_error = detail::catalogueEntry("orthonormality_error");
inline constexpr const QuantityInfo& rotation_determinant = detail::catalogueEntry("rotation_determinant");
inline constexpr const QuantityInfo& orientation_from_matrix = detail::catalogueEntry("orientation_from_matrix");

} // namespace rbw::q
