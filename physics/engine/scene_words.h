// The words of the scene's enumerations, spelled once: what a scene file writes for
// an InertiaConvention, a PlaneContactMode, a ContactModel, a PositionFix or a ManifoldSolver
// ("inertia_convention": "course-template"; docs/scene-format.md). The words belong to
// the enumerations, so they live beside them in the physics (as stageName() and the
// integrators' names do), and every room that shows or reads one uses these: the
// scene-format table (app/scene/scene_format.cpp), the run output's echo of a
// convention (app/output/json_output.cpp), the derivation templates' conditions
// (app/derivation/). Each list is in the order of its enumeration: a value is its index.
#pragma once

#include "physics/engine/inertia.h"
#include "physics/engine/scene.h"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace rbw {

inline constexpr std::array<std::string_view, 2> kInertiaConventionWords{"standard", "course-template"};
inline constexpr std::array<std::string_view, 2> kPlaneContactWords{"per-point", "average"};
inline constexpr std::array<std::string_view, 2> kContactModelWords{"course", "manifold"};
inline constexpr std::array<std::string_view, 3> kPositionFixWords{"ngs", "baumgarte", "none"};
inline constexpr std::array<std::string_view, 2> kManifoldSolverWords{"sequential-impulses", "soft-step"};

// An enumeration with one more value than its list has words fails here.
static_assert(static_cast<std::size_t>(InertiaConvention::CourseTemplate) + 1 == kInertiaConventionWords.size());
static_assert(static_cast<std::size_t>(PlaneContactMode::Average) + 1 == kPlaneContactWords.size());
static_assert(static_cast<std::size_t>(ContactModel::Manifold) + 1 == kContactModelWords.size());
static_assert(static_cast<std::size_t>(PositionFix::None) + 1 == kPositionFixWords.size());
static_assert(static_cast<std::size_t>(ManifoldSolver::SoftStep) + 1 == kManifoldSolverWords.size());

// The words of enumeration E, in its order.
template <typename E>
constexpr std::span<const std::string_view> sceneWords();
template <>
constexpr std::span<const std::string_view> sceneWords<InertiaConvention>() { return kInertiaConventionWords; }
template <>
constexpr std::span<const std::string_view> sceneWords<PlaneContactMode>() { return kPlaneContactWords; }
template <>
constexpr std::span<const std::string_view> sceneWords<ContactModel>() { return kContactModelWords; }
template <>
constexpr std::span<const std::string_view> sceneWords<PositionFix>() { return kPositionFixWords; }
template <>
constexpr std::span<const std::string_view> sceneWords<ManifoldSolver>() { return kManifoldSolverWords; }

// A value's word: sceneWord(ContactModel::Manifold) is "manifold".
template <typename E>
constexpr std::string_view sceneWord(E value)
{
    return sceneWords<E>()[static_cast<std::size_t>(value)];
}

// The value a word names; nullopt for a word that is none of E's (case matters).
template <typename E>
constexpr std::optional<E> sceneWordValue(std::string_view word)
{
    const std::span<const std::string_view> words = sceneWords<E>();
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] == word) return static_cast<E>(i);
    }
    return std::nullopt;
}

// The words of E as a message lists them: "\"ngs\", \"baumgarte\" or \"none\"" (the
// validation messages, "must be " + sceneWordChoices<PositionFix>()).
template <typename E>
std::string sceneWordChoices()
{
    const std::span<const std::string_view> words = sceneWords<E>();
    std::string text;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (i > 0) text += i + 1 == words.size() ? " or " : ", ";
        text += '"';
        text += words[i];
        text += '"';
    }
    return text;
}

// A value inside E's range (a scene built in code may cast any integer to E).
template <typename E>
constexpr bool isSceneWordValue(E value)
{
    return static_cast<std::size_t>(value) < sceneWords<E>().size();
}

static_assert(sceneWord(ContactModel::Manifold) == "manifold");
static_assert(sceneWordValue<PositionFix>("none") == PositionFix::None);
static_assert(!sceneWordValue<InertiaConvention>("Standard").has_value());

} // namespace rbw
