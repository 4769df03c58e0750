#include "physics/workbook/probes/template_tests.h"

#include <cmath>

namespace rbw::probes {

namespace {

// setupBaseTest(): two boxes 0.4 x 0.2 x 0.2 of mass 100; body 1 turned 45 deg about z
// (Quat(Vec3(0, 0, 1), M_PI * 0.25)) and moving.
std::vector<Command> baseSetup()
{
    return {addBody(Vec3(-0.1, -0.2, 0.1), Vec3(0.4, 0.2, 0.2), 100),
            addBody(Vec3(0.0, 0.2, 0.0), Vec3(0.4, 0.2, 0.2), 100),
            setOrientation(1, turn(45.0, Vec3(0, 0, 1))),
            setVelocity(1, Vec3(0.0, -0.1, 0.05))};
}

// TestRigidBodiesAfterForceApplication's scene: 200 N along z at the origin on body 0,
// four steps of 0.1 (the force acts in the first). The bodies stay 0.05 m apart.
Probe afterForceScene()
{
    Probe p{"template-after-force", "the template's TestRigidBodiesAfterForceApplication", baseSetup()};
    p.commands.push_back(applyForce(0, Vec3(0, 0, 0), Vec3(0, 0, 200)));
    for (int k = 0; k < 4; ++k) p.commands.push_back(step(0.1));
    p.commands.push_back(state(0));
    return p;
}

std::vector<TemplateTest> build()
{
    std::vector<TemplateTest> all;

    Probe init{"template-initialization", "the template's TestRigidBodiesInitialization", baseSetup()};
    init.commands.push_back(state(0));
    init.commands.push_back(state(1));
    all.push_back({"TestRigidBodiesInitialization", "", "the bodies as they were set up, before any step", init,
                   {{0, "x", Vec3(-0.1, -0.2, 0.1)},
                    {0, "v", Vec3::Zero()},
                    {0, "omega", Vec3::Zero()},
                    {1, "x", Vec3(0.0, 0.2, 0.0)},
                    {1, "v", Vec3(0.0, -0.1, 0.05)},
                    {1, "omega", Vec3::Zero()}}});

    // x = (-0.1, -0.2, 0.1 + 3 * 0.1 * 0.2) and v = 200/100 * 0.1 along z in every version;
    // omega is R^T I0^-1 R L (and, in 2018, the old quaternion product's r)
    const std::vector<TemplateAssert> linear{{0, "x", Vec3(-0.1, -0.2, 0.16)}, {0, "v", Vec3(0.0, 0.0, 0.2)}};
    std::vector<TemplateAssert> v2018 = linear, v2022 = linear;
    v2018.push_back({0, "omega", Vec3(5.9064, -1.7891, -1.0204)});
    v2022.push_back({0, "omega", Vec3(5.8590, -2.1106, -1.1391)});
    all.push_back({"TestRigidBodiesAfterForceApplication", "2018",
                   "the world inverse inertia R^T I0^-1 R (transposed-inertia) with the template's quaternion "
                   "product of 2018, whose cross product was reversed; R I0^-1 R^T gives omega_z = +1.0205",
                   afterForceScene(), v2018});
    all.push_back({"TestRigidBodiesAfterForceApplication", "December 2022",
                   "the world inverse inertia R^T I0^-1 R (transposed-inertia, the template's row-vector "
                   "matrices); R I0^-1 R^T gives omega = (5.9065, -1.7891, 1.0205)",
                   afterForceScene(), v2022});

    // Table 2.1 (docs/references.md §1): turned 90 deg about z, where R^T I0^-1 R =
    // R I0^-1 R^T, so either convention passes.
    Probe table{"template-table-2-1", "the template's TestRigidBodiesOneStepGivenTableTest",
                {addBody(Vec3(0, 0, 0), Vec3(1.0, 0.6, 0.5), 2), setOrientation(0, turn(90.0, Vec3(0, 0, 1))),
                 applyForce(0, Vec3(0.3, 0.5, 0.25), Vec3(1.0, 1.0, 0.0)), step(2.0), state(0)}};
    all.push_back({"TestRigidBodiesOneStepGivenTableTest", "",
                   "Table 2.1, turned 90 deg about z: both inertia conventions give the same numbers", table,
                   {{0, "x", Vec3::Zero()},
                    {0, "v", Vec3(1.0, 1.0, 0.0)},
                    {0, "omega", Vec3(-2.4, 4.9180, -1.7647)},
                    {0, "point velocity", Vec3(-1.11186, 0.929412, 2.67541), Vec3(-0.3, -0.5, -0.25)}}});
    return all;
}

} // namespace

const std::vector<TemplateTest>& templatePublicTests()
{
    static const std::vector<TemplateTest> all = build();
    return all;
}

std::optional<TemplateFailure> runTemplateTest(const TemplateTest& test, const Answers& given)
{
    for (std::size_t k = 0; k < test.asserts.size(); ++k) {
        const TemplateAssert& a = test.asserts[k];
        if (a.answer >= static_cast<int>(given.size()) || given[a.answer].size() < 9) {
            return TemplateFailure{static_cast<int>(k), 0, a.expected, Vec3::Constant(std::nan(""))};
        }
        const Answer& s = given[a.answer];
        const Vec3 x(s[0], s[1], s[2]), v(s[3], s[4], s[5]), omega(s[6], s[7], s[8]);
        Vec3 value = x;
        if (a.quantity == "v") value = v;
        if (a.quantity == "omega") value = omega;
        if (a.quantity == "point velocity") value = v + omega.cross(a.p_W - x);   // v + omega x (p - x)
        for (int i = 0; i < 3; ++i) {
            if (!(std::abs(value[i] - a.expected[i]) <= kTemplateTolerance)) {
                return TemplateFailure{static_cast<int>(k), i, a.expected, value};
            }
        }
    }
    return std::nullopt;
}

} // namespace rbw::probes
