#include "physics/engine/trace.h"

#include "physics/engine/quantities.h"

#include <type_traits>

namespace rbw {

const char* stageName(Stage s)
{
    switch (s) {
    case Stage::Forces: return "forces";
    case Stage::Integration: return "integration";
    case Stage::Collision: return "collision";
    case Stage::Correction: return "correction";
    case Stage::Probes: return "probes";
    }
    return "?";
}

const char* frameName(Frame f)
{
    switch (f) {
    case Frame::None: return "";
    case Frame::World: return "world";
    case Frame::Body: return "body";
    }
    return "?";
}

const char* indexKindName(IndexKind k)
{
    switch (k) {
    case IndexKind::None: return "";
    case IndexKind::Force: return "force";
    case IndexKind::Torque: return "torque";
    case IndexKind::Probe: return "probe";
    case IndexKind::Contact: return "contact";
    case IndexKind::RkStage: return "stage";
    case IndexKind::Correction: return "correction";
    }
    return "?";
}

std::string_view sourceFile(const TraceEntry& e)
{
    // The physics library is compiled with -fmacro-prefix-map=<source dir>/= (CMake), so
    // file_name() is already relative; a build without it keeps the absolute path, of
    // which the part from the last "physics/" on is the repository-relative one.
    // A build through ccache with a base_dir compiles "../physics/x.cpp" (relative to the
    // build tree), which the map does not touch: the leading "../" and "./" go too.
    std::string_view f = e.where.file_name();
    if (!f.empty() && f.front() == '/') {
        const size_t at = f.rfind("/physics/");
        if (at != std::string_view::npos) f.remove_prefix(at + 1);
    }
    while (f.starts_with("../") || f.starts_with("./")) f.remove_prefix(f.front() == '.' && f[1] == '.' ? 3 : 2);
    return f;
}

unsigned sourceLine(const TraceEntry& e)
{
    return static_cast<unsigned>(e.where.line());
}

std::string sourceText(const TraceEntry& e)
{
    return std::string(sourceFile(e)) + ":" + std::to_string(sourceLine(e));
}

const TraceEntry* StepTrace::find(std::string_view id, int body, int index) const
{
    for (const TraceEntry& e : entries) {
        if (e.body == body && e.index == index && id == e.info->id) {
            return &e;
        }
    }
    return nullptr;
}

namespace {

// The state fields a start-of-step value is read from, by the catalogue's ids.
enum class StartField { None, X, V, R, L, RotationMatrix, Iinv, Omega, ProbeP, ProbeV };

StartField startField(std::string_view id)
{
    if (id == q::position.id) return StartField::X;
    if (id == q::linear_velocity.id) return StartField::V;
    if (id == q::orientation.id) return StartField::R;
    if (id == q::angular_momentum.id) return StartField::L;
    if (id == q::rotation_matrix.id) return StartField::RotationMatrix;
    if (id == q::inverse_inertia_world.id) return StartField::Iinv;
    if (id == q::angular_velocity.id) return StartField::Omega;
    if (id == q::probe_position.id) return StartField::ProbeP;
    if (id == q::point_velocity.id) return StartField::ProbeV;
    return StartField::None;
}

} // namespace

bool hasStartValue(std::string_view id)
{
    return startField(id) != StartField::None;
}

std::vector<double> traceValueComponents(const TraceValue& value)
{
    return std::visit(
        [](const auto& v) -> std::vector<double> {
            using T = std::decay_t<decltype(v)>;
            if constexpr (std::is_same_v<T, double>) {
                return {v};
            } else if constexpr (std::is_same_v<T, Vec3>) {
                return {v.x(), v.y(), v.z()};
            } else if constexpr (std::is_same_v<T, Quat>) {
                return {v.w(), v.x(), v.y(), v.z()};
            } else {
                std::vector<double> out;
                out.reserve(9);
                for (int i = 0; i < 3; ++i) {
                    for (int j = 0; j < 3; ++j) out.push_back(v(i, j));
                }
                return out;
            }
        },
        value);
}

bool startValue(const StepTrace& trace, std::string_view id, int body, int index, TraceValue* out)
{
    const StartField f = startField(id);
    if (f == StartField::ProbeP || f == StartField::ProbeV) {
        if (index < 0 || index >= static_cast<int>(trace.start.probes.size())) return false;
        const ProbeSample& p = trace.start.probes[static_cast<size_t>(index)];
        if (p.body != body) return false;
        *out = f == StartField::ProbeP ? p.p_W : p.v_W;
        return true;
    }
    if (f == StartField::None || index != -1 || body < 0 || body >= static_cast<int>(trace.start.bodies.size())) {
        return false;
    }
    const BodyState& s = trace.start.bodies[static_cast<size_t>(body)];
    switch (f) {
    case StartField::X: *out = s.x_W; return true;
    case StartField::V: *out = s.v_W; return true;
    case StartField::R: *out = s.q_WB; return true;
    case StartField::L: *out = s.L_W; return true;
    case StartField::RotationMatrix: *out = s.R_WB; return true;
    case StartField::Iinv: *out = s.Iinv_W; return true;
    case StartField::Omega: *out = s.omega_W; return true;
    default: return false;
    }
}

} // namespace rbw
