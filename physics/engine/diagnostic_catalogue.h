// The one catalogue of the diagnostics' names (diagnostics.h): each energy and momentum
// of the whole world and of each body, with the id every output uses for it (the JSON
// fields of `rbw run`, the CSV columns, the plots), its plain symbol, what it is, its
// unit and where its value lives. As the quantity catalogue (quantity_catalogue.h) is
// for the traced quantities, this is for the diagnostics: nothing else spells these ids.
#pragma once

#include "physics/engine/diagnostics.h"

#include <cstddef>
#include <string_view>

namespace rbw {

// One diagnostic of the world (Diagnostics) or of a body (BodyDiagnostics): a scalar or
// a world-frame vector, exactly one of the two member pointers set.
template <typename Of>
struct DiagnosticInfo {
    std::string_view id;        // "total_energy"
    std::string_view symbol;    // plain UTF-8, "E"
    std::string_view meaning;   // "total energy E = T_trans + T_rot + V"
    std::string_view unit;      // UTF-8, "J"
    double Of::*scalar = nullptr;
    Vec3 Of::*vector = nullptr;   // world frame
};

// clang-format off
inline constexpr DiagnosticInfo<Diagnostics> kWorldDiagnostics[] = {
    {"kinetic_energy_translational", "T_trans", "translational kinetic energy Σ ½ M |v|²", "J",
     &Diagnostics::kineticTranslational, nullptr},
    {"kinetic_energy_rotational", "T_rot", "rotational kinetic energy Σ ½ ω·L", "J",
     &Diagnostics::kineticRotational, nullptr},
    {"kinetic_energy", "T", "kinetic energy T = T_trans + T_rot", "J", &Diagnostics::kinetic, nullptr},
    {"potential_energy", "V", "potential energy Σ −M g·x (0 at the origin)", "J", &Diagnostics::potential, nullptr},
    {"total_energy", "E", "total energy E = T_trans + T_rot + V", "J", &Diagnostics::total, nullptr},
    {"linear_momentum", "P", "total linear momentum P = Σ M v (world)", "kg·m/s", nullptr, &Diagnostics::P_W},
    {"angular_momentum_origin", "L_O", "angular momentum about the origin L_O = Σ (x × M v + L) (world)",
     "kg·m²/s", nullptr, &Diagnostics::L_O_W},
};

inline constexpr DiagnosticInfo<BodyDiagnostics> kBodyDiagnostics[] = {
    {"kinetic_energy_translational", "T_trans", "the body's translational kinetic energy ½ M |v|²", "J",
     &BodyDiagnostics::kineticTranslational, nullptr},
    {"kinetic_energy_rotational", "T_rot", "the body's rotational kinetic energy ½ ω·L", "J",
     &BodyDiagnostics::kineticRotational, nullptr},
    {"kinetic_energy", "T", "the body's kinetic energy T = T_trans + T_rot", "J", &BodyDiagnostics::kinetic, nullptr},
    {"angular_momentum", "L", "the body's angular momentum about its centre of mass (world)", "kg·m²/s",
     nullptr, &BodyDiagnostics::L_W},
    {"angular_momentum_norm", "|L|", "the length of the body's angular momentum", "kg·m²/s",
     &BodyDiagnostics::L_norm, nullptr},
};
// clang-format on

// The entry with this id; the catalogue's ids are unique (checked below).
template <typename Of, std::size_t N>
constexpr const DiagnosticInfo<Of>& diagnosticEntry(const DiagnosticInfo<Of> (&table)[N], std::string_view id)
{
    for (const DiagnosticInfo<Of>& d : table) {
        if (d.id == id) return d;
    }
    throw "no diagnostic with this id";   // a compile error in a constant expression
}

namespace detail {
template <typename Of, std::size_t N>
consteval bool diagnosticsWellFormed(const DiagnosticInfo<Of> (&table)[N])
{
    for (std::size_t i = 0; i < N; ++i) {
        if ((table[i].scalar == nullptr) == (table[i].vector == nullptr)) return false;   // exactly one value
        for (std::size_t j = i + 1; j < N; ++j) {
            if (table[i].id == table[j].id) return false;
        }
    }
    return true;
}
static_assert(diagnosticsWellFormed(kWorldDiagnostics));
static_assert(diagnosticsWellFormed(kBodyDiagnostics));
} // namespace detail

// Named handles for the code that picks one (the CSV's energy columns, the plots).
namespace diag {
inline constexpr const DiagnosticInfo<Diagnostics>& kinetic_translational =
    diagnosticEntry(kWorldDiagnostics, "kinetic_energy_translational");
inline constexpr const DiagnosticInfo<Diagnostics>& kinetic_rotational =
    diagnosticEntry(kWorldDiagnostics, "kinetic_energy_rotational");
inline constexpr const DiagnosticInfo<Diagnostics>& kinetic = diagnosticEntry(kWorldDiagnostics, "kinetic_energy");
inline constexpr const DiagnosticInfo<Diagnostics>& potential = diagnosticEntry(kWorldDiagnostics, "potential_energy");
inline constexpr const DiagnosticInfo<Diagnostics>& total = diagnosticEntry(kWorldDiagnostics, "total_energy");
inline constexpr const DiagnosticInfo<Diagnostics>& linear_momentum = diagnosticEntry(kWorldDiagnostics, "linear_momentum");
inline constexpr const DiagnosticInfo<Diagnostics>& angular_momentum_origin =
    diagnosticEntry(kWorldDiagnostics, "angular_momentum_origin");
} // namespace diag

} // namespace rbw
