#include "app/core/compact_trace.h"

namespace rbw {

CompactTrace::CompactTrace(const StepTrace& trace)
    : step_(trace.step), time_(trace.time), contacts_(trace.contacts), diagnostics_(trace.diagnostics), start_(trace.start)
{
    static_assert(sizeof(Header) == 24, "the packed header: two pointers and two ints");
    headers_.reserve(trace.entries.size());
    kinds_.reserve(trace.entries.size());
    values_.reserve(trace.entries.size() * 4);
    for (const TraceEntry& e : trace.entries) {
        headers_.push_back(Header{e.info, e.where, e.body, e.index});
        kinds_.push_back(static_cast<std::uint8_t>(e.value.index()));
        switch (e.value.index()) {
        case 0:
            values_.push_back(std::get<double>(e.value));
            break;
        case 1: {
            const Vec3& v = std::get<Vec3>(e.value);
            values_.insert(values_.end(), v.data(), v.data() + 3);
            break;
        }
        case 2: {
            const Quat& q = std::get<Quat>(e.value);   // Eigen's storage order x, y, z, w
            values_.insert(values_.end(), q.coeffs().data(), q.coeffs().data() + 4);
            break;
        }
        default: {
            const Mat3& m = std::get<Mat3>(e.value);   // column-major, as Eigen stores it
            values_.insert(values_.end(), m.data(), m.data() + 9);
            break;
        }
        }
    }
    values_.shrink_to_fit();
}

StepTrace CompactTrace::unpack() const
{
    StepTrace t;
    t.step = step_;
    t.time = time_;
    t.contacts = contacts_;
    t.diagnostics = diagnostics_;
    t.start = start_;
    t.entries.reserve(headers_.size());
    const double* v = values_.data();
    for (std::size_t i = 0; i < headers_.size(); ++i) {
        const Header& h = headers_[i];
        TraceValue value;
        switch (kinds_[i]) {
        case 0:
            value = *v;
            v += 1;
            break;
        case 1:
            value = Vec3(v[0], v[1], v[2]);
            v += 3;
            break;
        case 2: {
            Quat q;
            q.coeffs() = Eigen::Map<const Eigen::Vector4d>(v);
            value = q;
            v += 4;
            break;
        }
        default:
            value = Mat3(Eigen::Map<const Mat3>(v));
            v += 9;
            break;
        }
        t.entries.push_back(TraceEntry{h.info, h.body, h.index, value, h.where});
    }
    return t;
}

std::size_t CompactTrace::bytes() const
{
    return headers_.capacity() * sizeof(Header) + kinds_.capacity() + values_.capacity() * sizeof(double) +
           contacts_.capacity() * sizeof(ContactHeader) +
           start_.bodies.capacity() * sizeof(BodyState) + start_.probes.capacity() * sizeof(ProbeSample);
}

} // namespace rbw
