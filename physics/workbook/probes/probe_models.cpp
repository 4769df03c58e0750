#include "physics/workbook/probes/probe_models.h"

#include <algorithm>
#include <cstddef>

namespace rbw::probes {

const std::vector<ScopedMistake>& mistakeScopes()
{
    using M = Mistake;
    using S = ProbeScope;
    static const std::vector<ScopedMistake> all = {
        {M::VelocityBeforePosition, S::Motion, "x after a step with a force"},
        {M::OmegaBeforeOrientation, S::Motion, "r (and so omega) after a step with a torque"},
        {M::TransposedInertia, S::Motion, "omega of a body turned about a tilted axis"},
        {M::BodyInverseInertia, S::Motion, "omega of a turned body"},
        {M::InertiaNotInverted, S::Motion, "omega"},
        {M::TorqueReversed, S::Motion, "omega after an off-centre force"},
        {M::LeverArmFromOrigin, S::Motion, "omega of a body off the origin"},
        {M::MissingTimeStep, S::Motion, "v and omega when h != 1"},
        {M::QuaternionMissingHalf, S::Motion, "r, then omega, of a spinning body"},
        {M::QuaternionNotNormalised, S::Motion, "r, then omega, of a spinning body"},
        {M::HalfExtentsForSize, S::Motion, "omega"},
        {M::InertiaAxesSwapped, S::Motion, "omega of a box with three different moments"},
        {M::InertiaHalfExtentsWithoutThird, S::Motion, "omega (three times the right I0)"},
        {M::OmegaAccumulated, S::Motion, "omega of a body that already turns"},
        {M::InertiaFromOldOrientation, S::Motion, "omega of a body that turns during the step"},
        {M::InertiaNotUpdated, S::Motion, "omega from the second step on, of a body that turns"},
        {M::InertiaAccumulatedRotation, S::Motion, "omega of a turned body (its turns pile up in I^-1)"},
        {M::QuaternionRightMultiplied, S::Motion, "r, then omega, of a turned body that spins about a tilted axis"},
        {M::ForcesNotCleared, S::Motion, "v and omega in the steps after a force stops"},
        {M::GravityAlwaysOn, S::Motion, "v (the probes have no gravity)"},
        {M::OrientationZeroQuaternion, S::Motion, "omega of a spinning body whose orientation is never set"},
        {M::AngleInDegrees, S::HandOnly,
         "the initial r built from an angle by hand; the protocol sends r itself (set_orientation)"},
        {M::PointVelocityWithoutRotation, S::HandOnly,
         "a point's velocity v_p is written down only by hand; a simulator without contacts never "
         "forms it, and one with contacts is the collision group's impulse"},
        {M::PointVelocityCrossReversed, S::HandOnly, "the same: a point's velocity of the hand calculation"},
        {M::PointVelocityLeverArmFromOrigin, S::HandOnly, "the same: a point's velocity of the hand calculation"},
        {M::QuaternionWithoutHalfAngle, S::HandOnly,
         "the initial r built from an angle by hand; the protocol sends r itself (set_orientation)"},
        {M::RelativeVelocityReversed, S::Collision, "the impulse"},
        {M::ImpulseLinearOnly, S::Collision, "the impulse"},
        {M::ImpulseWithoutOnePlus, S::Collision, "the impulse"},
        {M::RestitutionOneMinus, S::Collision, "the impulse"},
        {M::NoSeparatingCheck, S::Collision, "an impulse on a separating contact"},
        {M::ImpulseLeverArmFromOrigin, S::Collision, "the impulse of a contact off the origin"},
        {M::ImpulseDenominatorMissingCross, S::Collision, "the impulse of an off-centre contact"},
        {M::ImpulseBodyInverseInertia, S::Collision, "the impulse of a turned body"},
    };
    return all;
}

std::optional<ProbeScope> scopeOf(Mistake m)
{
    for (const ScopedMistake& s : mistakeScopes()) {
        if (s.mistake == m) return s.scope;
    }
    return std::nullopt;
}

std::vector<ReplayModel> motionModels()
{
    std::vector<ReplayModel> models;
    for (const MistakeInfo& info : mistakeCatalogue()) {
        if (scopeOf(info.mistake) != ProbeScope::Motion) continue;
        for (int v = 0; v < info.variants; ++v) models.push_back({info.mistake, v});
    }
    return models;
}

Mistake sameSlotWinner(Mistake a, Mistake b)
{
    // Each slot's models in the order physics/workbook/checker/mistakes.cpp tests them:
    // the first one present wins.
    using M = Mistake;
    static const std::vector<std::vector<Mistake>> slots = {
        {M::BodyInverseInertia, M::InertiaNotInverted},   // angularVelocity(): omega = which matrix times L
        {M::InertiaNotUpdated, M::InertiaAccumulatedRotation,
         M::InertiaFromOldOrientation},                    // stepInverseInertia(): which world I^-1
        {M::ImpulseWithoutOnePlus, M::RestitutionOneMinus},   // handImpulse(): the numerator's factor
    };
    for (const std::vector<Mistake>& slot : slots) {
        const auto a_at = std::find(slot.begin(), slot.end(), a), b_at = std::find(slot.begin(), slot.end(), b);
        if (a_at != slot.end() && b_at != slot.end() && a != b) return a_at < b_at ? a : b;
    }
    return Mistake::None;
}

std::vector<ReplayModel> modelPairs(const std::vector<ReplayModel>& singles)
{
    std::vector<ReplayModel> pairs;
    for (std::size_t i = 0; i < singles.size(); ++i) {
        for (std::size_t k = i + 1; k < singles.size(); ++k) {
            const ReplayModel& a = singles[i];
            const ReplayModel& b = singles[k];
            if (a.isPair() || b.isPair() || a.mistake == Mistake::None || b.mistake == Mistake::None) continue;
            if (a.mistake == b.mistake || sameSlotWinner(a.mistake, b.mistake) != Mistake::None) continue;
            // the variant of whichever has variants (the other's is 0)
            pairs.push_back(ReplayModel{a.mistake, std::max(a.variant, b.variant), b.mistake});
        }
    }
    return pairs;
}

} // namespace rbw::probes
