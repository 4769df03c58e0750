// The integrators a scene, `rbw --integrator` and the app can choose by name.
#pragma once

#include "physics/integrator.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rbw {

struct IntegratorInfo {
    const char* name;
    const char* summary;   // one line: method, order, source
};

const std::vector<IntegratorInfo>& integratorCatalogue();

// nullptr if the name is unknown.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);

// "explicit-euler, ..." for error messages.
std::string integratorNames();

} // namespace rbw
