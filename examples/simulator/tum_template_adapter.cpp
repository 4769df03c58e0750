// tum_template_adapter.cpp: lets the Rigid Body Workbook drive YOUR simulator from the
// TUM Game Physics template (exercise 2, class RigidBodySystemSimulator) through the
// simulator protocol, docs/simulator-protocol.md. Copy this file next to your
// RigidBodySystemSimulator.cpp and build it as a console program (how: that doc).
//
// It reads one command per line on stdin, calls your class exactly the way the
// template's public tests do (SimulatorTester/PublicRigidBodiesTests.cpp: a new object
// with m_iTestCase = TESTCASEUSEDTORUNTEST for every scene), and answers `state` with
// one line "X Y Z VX VY VZ WX WY WZ" on stdout. Your class needs no changes.
// Anything your simulator prints (printf, cout) goes to stderr, so debug output cannot
// garble the answers.
#include "RigidBodySystemSimulator.h"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#ifdef _WIN32
#include <io.h>
#define dup _dup
#define dup2 _dup2
#define fileno _fileno
#define fdopen _fdopen
#else
#include <unistd.h>
#endif

#ifndef TESTCASEUSEDTORUNTEST
#define TESTCASEUSEDTORUNTEST 2   // the value in the template's RigidBodySystemSimulator.h
#endif

namespace {

int g_lineNo = 0;

// Malformed input: say which line and why, exit 2.
[[noreturn]] void badLine(const std::string& why)
{
    std::fprintf(stderr, "tum_template_adapter: line %d: %s\n", g_lineNo, why.c_str());
    std::exit(2);
}

}   // namespace

int main()
{
    // The answers go to the real stdout; stdout itself now points at stderr.
    std::fflush(stdout);
    FILE* answers = fdopen(dup(fileno(stdout)), "w");
    dup2(fileno(stderr), fileno(stdout));
    if (answers == nullptr) {
        std::fprintf(stderr, "tum_template_adapter: cannot open the answer stream\n");
        return 2;
    }

    // `reset` = a new object, as each public test starts with one.
    std::unique_ptr<RigidBodySystemSimulator> sim;
    const auto newScene = [&sim]() {
        sim = std::make_unique<RigidBodySystemSimulator>();
        sim->m_iTestCase = TESTCASEUSEDTORUNTEST;
        // Bodies are numbered 0, 1, 2, ... in add_body order, so a new object must have
        // none (the public tests need that too): build demo scenes in notifyCaseChanged.
        if (sim->getNumberOfRigidBodies() != 0) {
            std::fprintf(stderr, "tum_template_adapter: a new RigidBodySystemSimulator already has %d bodies; "
                         "it must start empty (create demo scenes in notifyCaseChanged, not the constructor)\n",
                         sim->getNumberOfRigidBodies());
            std::exit(1);
        }
    };
    newScene();

    std::string line;
    while (std::getline(std::cin, line)) {
        ++g_lineNo;
        std::istringstream in(line);
        std::string command;
        if (!(in >> command)) continue;   // blank line

        // Reads body index i and checks it exists.
        const auto body = [&]() {
            int i = -1;
            if (!(in >> i) || i < 0 || i >= sim->getNumberOfRigidBodies()) badLine("no such body in: " + line);
            return i;
        };
        double x, y, z, a, b, c;
        int i, mass;
        if (command == "reset") {
            newScene();
        } else if (command == "add_body") {
            // add_body X Y Z SX SY SZ MASS
            if (!(in >> x >> y >> z >> a >> b >> c >> mass)) badLine("expected add_body X Y Z SX SY SZ MASS");
            sim->addRigidBody(Vec3(x, y, z), Vec3(a, b, c), mass);
        } else if (command == "set_orientation") {
            // set_orientation I W X Y Z. The template's Quat(x, y, z, w) takes w LAST.
            i = body();
            double w;
            if (!(in >> w >> x >> y >> z)) badLine("expected set_orientation I W X Y Z");
            sim->setOrientationOf(i, Quat(x, y, z, w));
        } else if (command == "set_velocity") {
            i = body();
            if (!(in >> x >> y >> z)) badLine("expected set_velocity I VX VY VZ");
            sim->setVelocityOf(i, Vec3(x, y, z));
        } else if (command == "apply_force") {
            // apply_force I PX PY PZ FX FY FZ: force f at world point p
            i = body();
            if (!(in >> x >> y >> z >> a >> b >> c)) badLine("expected apply_force I PX PY PZ FX FY FZ");
            sim->applyForceOnBody(i, Vec3(x, y, z), Vec3(a, b, c));
        } else if (command == "step") {
            double h;
            if (!(in >> h)) badLine("expected step H");
            sim->simulateTimestep(static_cast<float>(h));
        } else if (command == "state") {
            // The template has no orientation getter, so the answer has 9 numbers.
            i = body();
            const Vec3 p = sim->getPositionOfRigidBody(i);
            const Vec3 v = sim->getLinearVelocityOfRigidBody(i);
            const Vec3 w = sim->getAngularVelocityOfRigidBody(i);
            std::fprintf(answers, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", double(p.x),
                         double(p.y), double(p.z), double(v.x), double(v.y), double(v.z), double(w.x),
                         double(w.y), double(w.z));
            std::fflush(answers);
        } else if (command == "quit") {
            return 0;
        } else {
            badLine("unknown command '" + command + "'");
        }
        std::string extra;
        if (in >> extra) badLine("unexpected '" + extra + "' at the end of: " + line);
    }
    return 0;
}
