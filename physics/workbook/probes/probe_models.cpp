#include "physics/workbook/probes/probe_models.h"

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

} // namespace rbw::probes
