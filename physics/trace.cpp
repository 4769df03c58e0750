#include "physics/trace.h"

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
    std::string_view f = e.where.file_name();
    if (!f.empty() && f.front() == '/') {
        const size_t at = f.rfind("/physics/");
        if (at != std::string_view::npos) f.remove_prefix(at + 1);
    }
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

} // namespace rbw
