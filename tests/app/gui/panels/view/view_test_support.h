// What the 3D view's tests share: a lesson's world stepped k times with the trace of
// its last step, and the view shown and exposed under Xvfb.
#pragma once

#include "app/gui/panels/view/scene_view.h"
#include "physics/engine/world.h"
#include "tests/test_support.h"

#include <QtTest>

#include <memory>

namespace rbw::test {

// A world stepped `steps` times, and the trace of its last step.
struct Stepped {
    std::unique_ptr<World> world;
    StepTrace trace;
    ViewSnapshot snapshot() const { return makeViewSnapshot(*world, world->stepIndex() > 0 ? &trace : nullptr); }
};

inline Stepped stepLesson(const QString& lesson, int steps)
{
    Stepped s;
    s.world = std::make_unique<World>(lessonScene(lesson + "/scene.json"));
    for (int k = 0; k < steps; ++k) {
        if (!s.world->step(&s.trace).ok) qFatal("lesson %s blew up at step %d", qPrintable(lesson), k);
    }
    return s;
}

inline void showView(SceneView& view, QSize size = {640, 480})
{
    view.resize(size);
    view.show();
    if (!QTest::qWaitForWindowExposed(&view)) qFatal("the view was never exposed");
}

} // namespace rbw::test
