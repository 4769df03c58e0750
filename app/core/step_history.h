// The history behind Step back: the last N states of the world, each with the trace
// of the step that produced it, so that stepping back shows the earlier step's
// numbers exactly as they were computed (they are stored, packed, not recomputed).
//
// A ring buffer: when full, the oldest entry is dropped. Entry 0 is the oldest state
// still kept; back() is the current one.
#pragma once

#include "app/core/compact_trace.h"
#include "physics/world.h"

#include <cstddef>
#include <deque>

namespace rbw {

struct HistoryEntry {
    WorldSnapshot state;   // the world after the step
    CompactTrace trace;    // that step's trace, packed (empty for the initial state)
    bool hasTrace = false;
};

class StepHistory {
public:
    // 1001 states: the current one and the 1000 before it.
    static constexpr std::size_t kDefaultCapacity = 1001;

    explicit StepHistory(std::size_t capacity = kDefaultCapacity) : capacity_(capacity < 2 ? 2 : capacity) {}

    std::size_t capacity() const { return capacity_; }
    std::size_t size() const { return entries_.size(); }
    bool empty() const { return entries_.empty(); }
    void clear() { entries_.clear(); }

    void push(HistoryEntry entry)
    {
        if (entries_.size() == capacity_) {
            entries_.pop_front();
        }
        entries_.push_back(std::move(entry));
    }

    // Drops the current entry; false if only one (or none) is left to go back to.
    bool pop()
    {
        if (entries_.size() < 2) {
            return false;
        }
        entries_.pop_back();
        return true;
    }

    const HistoryEntry& back() const { return entries_.back(); }
    // Entry i, 0 being the oldest kept (i < size()).
    const HistoryEntry& at(std::size_t i) const { return entries_.at(i); }
    // How many steps back are possible from here.
    std::size_t stepsBackAvailable() const { return entries_.empty() ? 0 : entries_.size() - 1; }

private:
    std::size_t capacity_;
    std::deque<HistoryEntry> entries_;
};

} // namespace rbw
