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
