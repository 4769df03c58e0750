// The TUM template's public tests (issue 23 item 4): the three tests of
// SimulatorTester/PublicRigidBodiesTests.cpp (GamePhysicsTUM/gamephysicstemplate, Ex2;
// docs/references.md §1) as protocol scenes with the numbers they assert, so that
// `rbw diagnose --simulator` can run them through the student's program and say which
// pass. TestRigidBodiesAfterForceApplication exists in two versions with different
// expected omega: the 2018 one and the December 2022 one (the template's current one).
// Both expect the template's world inverse inertia R^T I0^-1 R (its row-vector
// matrices; the checker's transposed-inertia), the 2018 one together with the
// quaternion product the template had then (its cross product reversed), so a correct
// simulator (R I0^-1 R^T) fails both; lesson 8 (lessons/08-conventions) shows the two
// conventions side by side.
//
// An assertion passes when |given - expected| <= 1e-4, the template's
// Assert::AreEqual(expected, (float)value, 0.0001f).
#pragma once

#include "physics/workbook/probes/probes.h"
#include "physics/workbook/probes/replay.h"

#include <optional>
#include <string>
#include <vector>

namespace rbw::probes {

constexpr double kTemplateTolerance = 1e-4;

// One Vec3 the test asserts: x, v or omega of a `state` answer, or the velocity
// v + omega x (p - x) of the world point p of that body.
struct TemplateAssert {
    int answer = 0;                  // which `state` answer of the scene
    std::string quantity;            // "x", "v", "omega" or "point velocity"
    Vec3 expected = Vec3::Zero();
    Vec3 p_W = Vec3::Zero();         // the point, for "point velocity"
};

struct TemplateTest {
    std::string name;       // the test's name in the template
    std::string version;    // "" (one version), "2018" or "December 2022"
    std::string expects;    // one sentence: what its numbers take for granted
    Probe scene;            // the test's setup as protocol commands
    std::vector<TemplateAssert> asserts;
};

// TestRigidBodiesInitialization, TestRigidBodiesAfterForceApplication (2018, then
// December 2022), TestRigidBodiesOneStepGivenTableTest.
const std::vector<TemplateTest>& templatePublicTests();

// The first failing assertion: which, the component (0-2), the numbers.
struct TemplateFailure {
    int assertIndex = 0;
    int component = 0;
    Vec3 expected = Vec3::Zero();
    Vec3 given = Vec3::Zero();
};

// nullopt: every assertion passes with `given` (one answer per `state` of the scene).
std::optional<TemplateFailure> runTemplateTest(const TemplateTest& test, const Answers& given);

} // namespace rbw::probes
