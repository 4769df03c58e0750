// mistakes.h: the mistake switches of the reference simulator (`--mistake ID`): every
// id of the checker's contract with its scope, and one flag per model the protocol can
// show. README.md lists each model with its equation; reference_simulator.h applies
// them where a student who makes the mistake would.
#pragma once

#include <string>

namespace rbwref {

struct MistakeDef {
    const char* id;
    const char* scope;   // "both", "sim" or "hand" (hand: the protocol cannot show it)
};

// Every id of the contract, in its order. Only "sim" and "both" ones are accepted.
inline const MistakeDef kMistakeDefs[] = {
    {"velocity-before-position", "both"},
    {"omega-before-orientation", "both"},
    {"transposed-inertia", "both"},
    {"body-inverse-inertia", "both"},
    {"inertia-not-inverted", "both"},
    {"torque-reversed", "both"},
    {"lever-arm-from-origin", "both"},
    {"missing-time-step", "both"},
    {"quaternion-missing-half", "both"},
    {"quaternion-not-normalised", "both"},
    {"half-extents-for-size", "both"},
    {"point-velocity-without-rotation", "hand"},
    {"relative-velocity-reversed", "both"},
    {"impulse-linear-only", "both"},
    {"impulse-without-one-plus", "both"},
    {"inertia-from-old-orientation", "both"},
    {"inertia-half-extents-without-third", "both"},
    {"inertia-axes-swapped", "both"},
    {"inertia-not-updated", "sim"},
    {"inertia-accumulated-rotation", "sim"},
    {"quaternion-right-multiplied", "both"},
    {"omega-accumulated", "both"},
    {"forces-not-cleared", "sim"},
    {"gravity-always-on", "sim"},
    {"orientation-zero-quaternion", "sim"},
    {"quaternion-without-half-angle", "hand"},
    {"angle-in-degrees", "hand"},
    {"point-velocity-lever-arm-from-origin", "hand"},
    {"point-velocity-cross-reversed", "hand"},
    {"restitution-one-minus", "both"},
    {"no-separating-check", "both"},
    {"impulse-body-inverse-inertia", "both"},
    {"impulse-lever-arm-from-origin", "both"},
    {"impulse-denominator-missing-cross", "both"},
};

struct Mistakes {
    bool velocityBeforePosition = false, omegaBeforeOrientation = false, transposedInertia = false,
         bodyInverseInertia = false, inertiaNotInverted = false, torqueReversed = false,
         leverArmFromOrigin = false, missingTimeStep = false, quaternionMissingHalf = false,
         quaternionNotNormalised = false, halfExtentsForSize = false, relativeVelocityReversed = false,
         impulseLinearOnly = false, impulseWithoutOnePlus = false, inertiaFromOldOrientation = false,
         inertiaHalfExtentsWithoutThird = false, inertiaAxesSwapped = false, inertiaNotUpdated = false,
         inertiaAccumulatedRotation = false, quaternionRightMultiplied = false, omegaAccumulated = false,
         forcesNotCleared = false, gravityAlwaysOn = false, orientationZeroQuaternion = false,
         restitutionOneMinus = false, noSeparatingCheck = false, impulseBodyInverseInertia = false,
         impulseLeverArmFromOrigin = false, impulseDenominatorMissingCross = false;

    // Switches the model `id` on; false if `id` is not a sim/both model.
    bool enable(const std::string& id)
    {
        struct Entry { const char* id; bool Mistakes::*flag; };
        static const Entry entries[] = {
            {"velocity-before-position", &Mistakes::velocityBeforePosition},
            {"omega-before-orientation", &Mistakes::omegaBeforeOrientation},
            {"transposed-inertia", &Mistakes::transposedInertia},
            {"body-inverse-inertia", &Mistakes::bodyInverseInertia},
            {"inertia-not-inverted", &Mistakes::inertiaNotInverted},
            {"torque-reversed", &Mistakes::torqueReversed},
            {"lever-arm-from-origin", &Mistakes::leverArmFromOrigin},
            {"missing-time-step", &Mistakes::missingTimeStep},
            {"quaternion-missing-half", &Mistakes::quaternionMissingHalf},
            {"quaternion-not-normalised", &Mistakes::quaternionNotNormalised},
            {"half-extents-for-size", &Mistakes::halfExtentsForSize},
            {"relative-velocity-reversed", &Mistakes::relativeVelocityReversed},
            {"impulse-linear-only", &Mistakes::impulseLinearOnly},
            {"impulse-without-one-plus", &Mistakes::impulseWithoutOnePlus},
            {"inertia-from-old-orientation", &Mistakes::inertiaFromOldOrientation},
            {"inertia-half-extents-without-third", &Mistakes::inertiaHalfExtentsWithoutThird},
            {"inertia-axes-swapped", &Mistakes::inertiaAxesSwapped},
            {"inertia-not-updated", &Mistakes::inertiaNotUpdated},
            {"inertia-accumulated-rotation", &Mistakes::inertiaAccumulatedRotation},
            {"quaternion-right-multiplied", &Mistakes::quaternionRightMultiplied},
            {"omega-accumulated", &Mistakes::omegaAccumulated},
            {"forces-not-cleared", &Mistakes::forcesNotCleared},
            {"gravity-always-on", &Mistakes::gravityAlwaysOn},
            {"orientation-zero-quaternion", &Mistakes::orientationZeroQuaternion},
            {"restitution-one-minus", &Mistakes::restitutionOneMinus},
            {"no-separating-check", &Mistakes::noSeparatingCheck},
            {"impulse-body-inverse-inertia", &Mistakes::impulseBodyInverseInertia},
            {"impulse-lever-arm-from-origin", &Mistakes::impulseLeverArmFromOrigin},
            {"impulse-denominator-missing-cross", &Mistakes::impulseDenominatorMissingCross},
        };
        for (const Entry& e : entries) {
            if (id == e.id) {
                this->*e.flag = true;
                return true;
            }
        }
        return false;
    }
};

}   // namespace rbwref
