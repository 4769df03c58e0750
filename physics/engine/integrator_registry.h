// The integrators a scene, `rbw --integrator` and the app can choose by name.
#pragma once

#include "physics/engine/integrator.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rbw {

struct IntegratorInfo {
    const char* name;
    const char* summary;   // one line: method, order, source
    int order = 1;         // global order of accuracy: error ~ h^order (measured in tests/physics/engine/integrators)
    const char* title = "";   // for headings: "classical Runge-Kutta (RK4)"
};

// The catalogue's entry for this name; nullptr if the name is unknown.
const IntegratorInfo* findIntegrator(std::string_view name);

// In the order `rbw integrators` lists them: explicit-euler first.
const std::vector<IntegratorInfo>& integratorCatalogue();

// nullptr if the name is unknown.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);

// "explicit-euler, ..." for error messages.
std::string integratorNames();

} // namespace rbw
