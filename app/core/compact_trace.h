// A step trace packed for the history: the same entries, bit for bit, in about half
// the memory. A TraceEntry is 112 bytes whatever its value (the variant is as large
// as a 3x3 matrix); packed, each entry keeps a 24-byte header (with the source
// location of the statement that computed it, and the body and index as full ints,
// so any count of forces, probes or contacts a scene can have survives), one byte
// for its kind and only the doubles its value has (1, 3, 4 or 9). 1000 steps of 50
// boxes take about 100 MB instead of 220 MB. unpack(pack(t)) == t exactly: the
// doubles and indices are copied, never converted.
#pragma once

#include "physics/engine/trace.h"

#include <cstdint>
#include <source_location>
#include <vector>

namespace rbw {

class CompactTrace {
public:
    CompactTrace() = default;
    explicit CompactTrace(const StepTrace& trace);

    StepTrace unpack() const;
    std::size_t bytes() const;

private:
    struct Header {
        const QuantityInfo* info;
        std::source_location where;
        decltype(TraceEntry::body) body;
        decltype(TraceEntry::index) index;   // as wide as the entry's: no count wraps
    };
    long step_ = 0;
    double time_ = 0.0;
    std::vector<Header> headers_;
    std::vector<std::uint8_t> kinds_;   // per entry, the variant's alternative: 0 double, 1 Vec3, 2 Quat, 3 Mat3
    std::vector<double> values_;
    std::vector<ContactHeader> contacts_;
    Diagnostics diagnostics_;
    StartOfStep start_;   // the state the step started from, as it was
};

} // namespace rbw
