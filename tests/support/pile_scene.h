// A pile the tests use to load the manifold model beyond its comfortable size: n unit
// boxes of 1 kg, all centred at (0, y, 0) above a ground plane y = 0, so every pair
// overlaps and every box touches the ground (n² contact pairs in one step).
#pragma once

#include <QJsonArray>
#include <QJsonObject>
#include <QString>

namespace rbw::test {

struct PileSpec {
    int boxes = 10;
    double y = 0.5;            // every box's centre height (m); 0.5 rests a unit box on the ground
    double dt = 0.01;          // s
    int steps = 2;
    QString boxPrefix = QStringLiteral("box ");   // box names: prefix + index
};

inline QJsonObject pileScene(const PileSpec& spec)
{
    QJsonArray bodies;
    for (int i = 0; i < spec.boxes; ++i) {
        bodies.append(QJsonObject{{"name", spec.boxPrefix + QString::number(i)},
                                  {"size", QJsonArray{1, 1, 1}},
                                  {"mass", 1},
                                  {"position", QJsonArray{0, spec.y, 0}}});
    }
    return QJsonObject{{"name", "pile"},
                       {"dt", spec.dt},
                       {"steps", spec.steps},
                       {"integrator", "symplectic-euler"},
                       {"gravity", QJsonArray{0, -9.81, 0}},
                       {"contact_model", "manifold"},
                       {"planes", QJsonArray{QJsonObject{{"name", "ground"},
                                                         {"point", QJsonArray{0, 0, 0}},
                                                         {"normal", QJsonArray{0, 1, 0}}}}},
                       {"bodies", bodies}};
}

} // namespace rbw::test
