// rbw_rain_probe: the box rain of rain_scene.h in our manifold model alone, one run, for
// looking inside it (issue 19): where the deepest box-box overlaps are and a target for
// `perf record` with nothing but our solver in it (docs/performance.md, "Three engines").
//
//   ./build/bench/rbw_rain_probe [--solver soft-step|sequential-impulses]
//                                [--integrator NAME] [--boxes N] [--substeps N] [--sleep 0|1]
//                                [--threads 1|2]
//
// Prints the time per step (in all and in each second), the outcome (rain::measure, the same as rbw_bench_rain's
// table), the deepest overlap every second, and the overlapping pairs at the end by
// the kind of contact:
//   level      the lower box's storey, round(y_lower - 0.5) for a box resting on another
//              (0: on the ground), for a pair whose SAT normal is within 45 degrees of y
//   side       a pair whose normal is closer to horizontal (two neighbouring columns)
// and the ten deepest pairs with their normal, feature and the tilt of both boxes.
#include "bench/rain_scene.h"

#include "physics/engine/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

namespace {

using rain::ourBoxes;

// The angle between a box's axis nearest to world y and world y [deg]
double tiltDegrees(const rbw::BoxPose& pose)
{
    const double up = pose.R_WB.row(1).cwiseAbs().maxCoeff();
    return std::acos(std::min(1.0, up)) * 180.0 / 3.14159265358979323846;
}

struct Pair {
    int i, j;
    rbw::ContactGeometry hit;
};

std::vector<Pair> overlappingPairs(const std::vector<rain::FinalBox>& boxes)
{
    std::vector<rbw::Aabb> aabbs;
    for (const rain::FinalBox& b : boxes) aabbs.push_back(rbw::boxAabb(b.pose));
    rbw::AabbTree tree;
    std::vector<std::pair<int, int>> pairs;
    rbw::BroadPhaseStats stats;
    tree.findPairs(aabbs, std::vector<char>(boxes.size(), 1), pairs, stats);
    std::vector<Pair> out;
    for (const auto& [i, j] : pairs) {
        const std::optional<rbw::ContactGeometry> hit =
            rbw::collideBoxBoxSAT(boxes[static_cast<std::size_t>(i)].pose, boxes[static_cast<std::size_t>(j)].pose);
        if (hit && hit->depth > 0.0) out.push_back(Pair{i, j, *hit});
    }
    std::sort(out.begin(), out.end(), [](const Pair& a, const Pair& b) { return a.hit.depth > b.hit.depth; });
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    int n = 1000;
    std::string integrator = "symplectic-euler";
    std::string solver = "soft-step";
    int substeps = 0;
    int sleep = -1;
    int threads = 2;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--boxes") == 0) n = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--integrator") == 0) integrator = argv[i + 1];
        if (std::strcmp(argv[i], "--solver") == 0) solver = argv[i + 1];
        if (std::strcmp(argv[i], "--substeps") == 0) substeps = std::max(1, std::atoi(argv[i + 1]));
        if (std::strcmp(argv[i], "--sleep") == 0) sleep = std::atoi(argv[i + 1]);
        if (std::strcmp(argv[i], "--threads") == 0) threads = std::clamp(std::atoi(argv[i + 1]), 1, 2);
    }
    rbw::SceneDef scene = rain::rainScene(n, rbw::ContactModel::Manifold, integrator);
    scene.solver = solver == "sequential-impulses" ? rbw::ManifoldSolver::SequentialImpulses : rbw::ManifoldSolver::SoftStep;
    if (substeps > 0) scene.substeps = substeps;
    if (sleep >= 0) scene.sleep = sleep != 0;
    rbw::WorldOptions options;
    options.contactThreads = threads;
    rbw::World world(std::move(scene), options);
    std::vector<rain::FinalBox> before;
    double seconds = 0.0;
    std::vector<double> perSecond;   // ms per step in each second of the rain
    double secondStart = 0.0;
    std::printf("%d boxes, %s, %s, %d thread(s)\ndeepest box-box overlap at the end of each second [cm]:", n, solver.c_str(),
                integrator.c_str(), threads);
    for (int k = 1; k <= rain::kSteps; ++k) {
        const auto start = std::chrono::steady_clock::now();
        const rbw::StepStatus& status = world.step(nullptr);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (!status.ok) {
            std::printf("\nstopped in step %d: %s\n", k, status.message.c_str());
            return 1;
        }
        if (k == rain::kLastSecond) before = ourBoxes(world);
        if (k % 60 == 0) {
            perSecond.push_back(1000.0 * (seconds - secondStart) / 60.0);
            secondStart = seconds;
            const std::vector<Pair> pairs = overlappingPairs(ourBoxes(world));
            std::printf(" %.2f", pairs.empty() ? 0.0 : 100.0 * pairs.front().hit.depth);
            std::fflush(stdout);
        }
    }
    std::printf("\nms per step in each second:");
    for (const double ms : perSecond) std::printf(" %.2f", ms);
    const std::vector<rain::FinalBox> after = ourBoxes(world);
    const rain::Outcome o = rain::measure(after, before);
    std::printf("\n%.3f ms/step; KE %.3g J, > 0.01 m/s %d, > 0.1 m/s %d, asleep %d, overlap %.2f cm, below ground %.1f mm, "
                "mean height %.3f m, drift %.2f cm\n",
                1000.0 * seconds / rain::kSteps, o.kineticEnergy, o.moving, o.moving01, o.sleeping, 100.0 * o.overlap,
                1000.0 * o.below, o.meanHeight, 100.0 * o.drift);

    const std::vector<Pair> pairs = overlappingPairs(after);
    // Per storey (stacked pairs) and sideways: count, > 5 mm, > 1 cm, deepest
    struct Row {
        int count = 0, over5 = 0, over10 = 0;
        double deepest = 0.0;
    };
    std::vector<Row> levels(12);
    Row side;
    for (const Pair& p : pairs) {
        const rain::FinalBox& A = after[static_cast<std::size_t>(p.i)];
        const rain::FinalBox& B = after[static_cast<std::size_t>(p.j)];
        Row* row = &side;
        if (std::abs(p.hit.n_W.y()) > std::sqrt(0.5)) {
            const double lower = std::min(A.pose.c_W.y(), B.pose.c_W.y());
            const int level = std::clamp(static_cast<int>(std::lround(lower - 0.5)), 0, 11);
            row = &levels[static_cast<std::size_t>(level)];
        }
        ++row->count;
        if (p.hit.depth > 0.005) ++row->over5;
        if (p.hit.depth > 0.01) ++row->over10;
        row->deepest = std::max(row->deepest, p.hit.depth);
    }
    std::printf("\n| contact | pairs | > 5 mm | > 1 cm | deepest [mm] |\n| --- | ---: | ---: | ---: | ---: |\n");
    for (std::size_t l = 0; l < levels.size(); ++l) {
        if (levels[l].count == 0) continue;
        std::printf("| stacked, lower box in storey %zu | %d | %d | %d | %.2f |\n", l, levels[l].count, levels[l].over5,
                    levels[l].over10, 1000.0 * levels[l].deepest);
    }
    std::printf("| side by side | %d | %d | %d | %.2f |\n", side.count, side.over5, side.over10, 1000.0 * side.deepest);
    std::printf("\nthe deepest pairs: i j depth[mm] n_W feature(axis) y_i y_j tilt_i tilt_j [deg] asleep\n");
    for (std::size_t k = 0; k < pairs.size() && k < 10; ++k) {
        const Pair& p = pairs[k];
        const rain::FinalBox& A = after[static_cast<std::size_t>(p.i)];
        const rain::FinalBox& B = after[static_cast<std::size_t>(p.j)];
        std::printf("%4d %4d %6.2f (%+.2f %+.2f %+.2f) %2d %.3f %.3f %5.1f %5.1f %d%d\n", p.i, p.j, 1000.0 * p.hit.depth,
                    p.hit.n_W.x(), p.hit.n_W.y(), p.hit.n_W.z(), p.hit.axis, A.pose.c_W.y(), B.pose.c_W.y(),
                    tiltDegrees(A.pose), tiltDegrees(B.pose), A.asleep ? 1 : 0, B.asleep ? 1 : 0);
    }
    return 0;
}
