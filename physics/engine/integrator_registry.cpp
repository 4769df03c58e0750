#include "physics/engine/integrator_registry.h"

#include "physics/engine/integrators/explicit_euler.h"
#include "physics/engine/integrators/implicit_gyroscopic.h"
#include "physics/engine/integrators/implicit_midpoint.h"
#include "physics/engine/integrators/midpoint.h"
#include "physics/engine/integrators/rk4.h"
#include "physics/engine/integrators/rotation_matrix.h"
#include "physics/engine/integrators/rotation_matrix_orthonormalised.h"
#include "physics/engine/integrators/symplectic_euler.h"

namespace rbw {

const std::vector<IntegratorInfo>& integratorCatalogue()
{
    static const std::vector<IntegratorInfo> catalogue = {
        {ExplicitEuler::kName,
         "explicit Euler in the TUM algorithm's order, first order (docs/references.md §1)", 1,
         "explicit Euler"},
        {SymplecticEuler::kName,
         "symplectic Euler: v and L first, then x and r with the new v and omega, first order (Box2D, Bullet)", 1,
         "symplectic Euler"},
        {Midpoint::kName, "explicit midpoint rule (RK2) on (x, r, P, L), second order (Runge 1895)", 2,
         "explicit midpoint (RK2)"},
        {Rk4::kName, "classical Runge-Kutta on (x, r, P, L), r renormalised, fourth order (Kutta 1901)", 4,
         "classical Runge–Kutta (RK4)"},
        {ImplicitGyroscopic::kName,
         "one Newton step of implicit Euler on the body-frame gyroscopic term, first order (Catto, GDC 2015; Bullet)",
         1, "implicit gyroscopic Euler"},
        {ImplicitMidpoint::kName,
         "implicit midpoint on the body-frame L with a Cayley rotation, second order, conserves |L| and T "
         "(Hairer-Lubich-Wanner VII.5)",
         2, "implicit midpoint"},
        {RotationMatrix::kName,
         "R <- R + h [omega]x R without orthonormalisation: R drifts from a rotation, first order (Napier practical 6)",
         1, "rotation-matrix Euler"},
        {RotationMatrixOrthonormalised::kName,
         "R <- R + h [omega]x R, then the nearest rotation (polar/SVD), first order (Napier practical 6)", 1,
         "rotation-matrix Euler, orthonormalised"},
    };
    return catalogue;
}

const IntegratorInfo* findIntegrator(std::string_view name)
{
    for (const IntegratorInfo& info : integratorCatalogue()) {
        if (name == info.name) return &info;
    }
    return nullptr;
}

std::unique_ptr<Integrator> makeIntegrator(std::string_view name)
{
    if (name == ExplicitEuler::kName) {
        return std::make_unique<ExplicitEuler>();
    }
    if (name == SymplecticEuler::kName) {
        return std::make_unique<SymplecticEuler>();
    }
    if (name == Midpoint::kName) {
        return std::make_unique<Midpoint>();
    }
    if (name == Rk4::kName) {
        return std::make_unique<Rk4>();
    }
    if (name == ImplicitGyroscopic::kName) {
        return std::make_unique<ImplicitGyroscopic>();
    }
    if (name == ImplicitMidpoint::kName) {
        return std::make_unique<ImplicitMidpoint>();
    }
    if (name == RotationMatrix::kName) {
        return std::make_unique<RotationMatrix>();
    }
    if (name == RotationMatrixOrthonormalised::kName) {
        return std::make_unique<RotationMatrixOrthonormalised>();
    }
    return nullptr;
}

std::string integratorNames()
{
    std::string names;
    for (const IntegratorInfo& info : integratorCatalogue()) {
        if (!names.empty()) {
            names += ", ";
        }
        names += info.name;
    }
    return names;
}

} // namespace rbw
