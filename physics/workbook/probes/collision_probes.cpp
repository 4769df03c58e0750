// The collision group of the probes (issue 23, probes.h): two boxes whose corner hits
// a face, off the origin, turned about tilted axes and spinning (an off-centre push in
// the first step), asked after every step. The collision replay
// (collision_replay.h) and the distinguishability test (tests/physics/workbook/probes/)
// prove that together they separate every collision model and fit the student's c.
#include "physics/workbook/probes/probes.h"

namespace rbw::probes {

namespace {

// `steps` steps of h, each followed by `state` of both bodies.
void stepAndAsk(std::vector<Command>& commands, int steps, double h)
{
    for (int k = 0; k < steps; ++k) {
        commands.push_back(step(h));
        commands.push_back(state(0));
        commands.push_back(state(1));
    }
}

std::vector<Probe> buildCollisionProbes()
{
    std::vector<Probe> all;

    // 1. A turned cube (body 1) falls corner first on the top face of a wide, tilted slab
    // (body 0, axis a_1 of the SAT: vertex on A's face), both off the origin and pushed
    // off-centre in the first step. The contact is far from both centres (the rotational
    // terms of the impulse's denominator, its lever arms from the centres: impulse-
    // linear-only, impulse-denominator-missing-cross, impulse-lever-arm-from-origin);
    // the step after the impulse the boxes still overlap but separate
    // (no-separating-check).
    Probe corner{"collision-01", "a turned cube falls corner first on a tilted slab, both pushed off-centre", {}, true};
    corner.commands = {addBody(Vec3(2.0, 0.5, -1.0), Vec3(2.0, 0.5, 1.6), 4),
                       addBody(Vec3(2.3, 1.33, -0.8), Vec3(0.6, 0.6, 0.6), 1),
                       setOrientation(0, turn(15.0, Vec3(1, 0, 2))),
                       setOrientation(1, turn(50.0, Vec3(1, 1, 0.3))),
                       setVelocity(1, Vec3(0.1, -1.2, 0.2)),
                       state(0),
                       state(1),
                       applyForce(1, Vec3(2.45, 1.5, -0.7), Vec3(1.0, 0.0, -0.5)),
                       applyForce(0, Vec3(2.8, 0.6, -0.4), Vec3(0.0, 5.0, 1.0))};
    stepAndAsk(corner.commands, 3, 0.05);
    all.push_back(corner);

    // 2. The other way round: a small turned box (body 0, A) flies sideways into the face
    // of a taller box (body 1, B; axis b_0: A's corner on B's face), both spinning, masses
    // 2 and 3; the next step they overlap while separating. B's orientation is never set
    // (add_body's identity), so a simulator that leaves it (0, 0, 0, 0)
    // (orientation-zero-quaternion) shows it here too.
    Probe side{"collision-02", "a small turned box flies corner first into the side of a taller spinning box", {}, true};
    side.commands = {addBody(Vec3(-3.47, 2.1, 4.1), Vec3(0.5, 0.8, 0.4), 2),
                     addBody(Vec3(-2.5, 2.0, 4.0), Vec3(0.6, 1.5, 1.2), 3),
                     setOrientation(0, turn(40.0, Vec3(0.3, 1, 1))),
                     setVelocity(0, Vec3(1.5, 0.1, -0.1)),
                     applyForce(0, Vec3(-3.3, 2.3, 4.0), Vec3(2.0, -1.0, 0.0)),
                     applyForce(1, Vec3(-2.4, 2.5, 4.3), Vec3(1.0, 0.5, -1.0))};
    stepAndAsk(side.commands, 5, 0.05);
    all.push_back(side);

    // 3. A turned cube (body 1) starts with its corner in the top face of a tilted slab
    // (body 0) and moves away: the contact separates in every step while the boxes
    // overlap. A simulator that checks the sign applies no impulse; one without the
    // check (no-separating-check) pulls the boxes together, and one whose v_rel is
    // reversed (relative-velocity-reversed, which applies no impulse when the boxes
    // approach) pushes them apart, so its c can be fitted here.
    Probe apart{"collision-03", "a turned cube starts with its corner in a tilted slab and moves away from it", {}, true};
    apart.commands = {addBody(Vec3(-2.0, 2.0, 1.0), Vec3(2.0, 0.5, 1.6), 3),
                      addBody(Vec3(-1.7, 2.68, 1.2), Vec3(0.6, 0.6, 0.6), 2),
                      setOrientation(0, turn(15.0, Vec3(1, 0, 2))),
                      setOrientation(1, turn(50.0, Vec3(1, 1, 0.3))),
                      setVelocity(1, Vec3(0.1, 0.4, -0.1)),
                      state(0),
                      state(1),
                      applyForce(1, Vec3(-1.6, 2.8, 1.3), Vec3(1.0, 0.0, 0.5)),
                      applyForce(0, Vec3(-1.4, 2.1, 1.3), Vec3(0.0, -1.0, 2.0))};
    stepAndAsk(apart.commands, 4, 0.05);
    all.push_back(apart);
    return all;
}

} // namespace

const std::vector<Probe>& collisionProbes()
{
    static const std::vector<Probe> all = buildCollisionProbes();
    return all;
}

} // namespace rbw::probes
