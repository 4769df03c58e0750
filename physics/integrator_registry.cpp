#include "physics/integrator_registry.h"

#include "physics/integrators/explicit_euler.h"

namespace rbw {

const std::vector<IntegratorInfo>& integratorCatalogue()
{
    static const std::vector<IntegratorInfo> catalogue = {
        {ExplicitEuler::kName,
         "explicit Euler in the TUM algorithm's order, first order (reference.md section 1)"},
    };
    return catalogue;
}

std::unique_ptr<Integrator> makeIntegrator(std::string_view name)
{
    if (name == ExplicitEuler::kName) {
        return std::make_unique<ExplicitEuler>();
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
