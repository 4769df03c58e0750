// The contact problems of the accuracy lab (issue 11, docs/accuracy-lab.md): scenes
// whose right answer is known without an exact solution, because the boxes should
// end at rest without overlap:
//   resting-box  one unit box resting on the ground, at rest: it should not move;
//   tower        10 unit boxes stacked on the ground, at rest: the tower should stand;
//   rain         N unit boxes in layers of 10 x 10, 1.5 m apart, the lowest at 3 m,
//                each turned by up to 0.2 rad (fixed seed), falling onto the ground:
//                the pile should come to rest without overlap.
// Every problem: unit boxes of M = 1 kg, g = 9.81 m/s^2, mu = 0.5, c = 0, h = 1/60 s,
// 600 steps (10 s), symplectic Euler; the course model with its position correction.
//
// And the measure of a state that every model and engine is judged by, taken with the
// course's own narrow phases (an instrument independent of the model measured):
//   overlap   the deepest box-box overlap: the SAT overlap of each pair whose AABBs
//             overlap (engine/course/box_box_sat.h), the largest of those      [m]
//   below     how far the lowest box corner is below a plane                   [m]
//   KE        sum of 1/2 M |v|^2 + 1/2 omega . L                               [J]
//   moving    bodies faster than 0.01 m/s                                      [-]
#pragma once

#include "physics/engine/body.h"
#include "physics/engine/scene.h"

#include <optional>
#include <string_view>
#include <vector>

namespace rbw::lab {

enum class ContactProblem { RestingBox, Tower, Rain };

const char* contactProblemName(ContactProblem p);   // "resting-box", "tower", "rain"
std::optional<ContactProblem> contactProblemFromName(std::string_view name);
// "resting-box, tower, rain", for messages
const char* contactProblemNames();

// The problem's scene in this model; rainBoxes is N for the rain (ignored otherwise).
SceneDef contactProblemScene(ContactProblem p, ContactModel model, int rainBoxes = 100);

struct ContactMeasure {
    double deepestOverlap = 0.0;   // [m]
    double deepestBelow = 0.0;     // [m]
    double kineticEnergy = 0.0;    // [J]
    int moving = 0;                // |v| > 0.01 m/s
};

// The measure of every box body of the scene in these states (fixed bodies count for
// overlap, not for KE or motion).
ContactMeasure measureContacts(const SceneDef& scene, const std::vector<MassProperties>& mass,
                               const std::vector<BodyState>& states);

} // namespace rbw::lab
