// The history behind Step back and the history scrubber: the last N states of the
// world, each with the trace of the step that produced it, so that going back shows
// the earlier step's numbers exactly as they were computed (they are stored, packed,
// not recomputed).
//
// A ring buffer with a cursor, like an editor's undo stack: entry 0 is the oldest
// state still kept, last() the newest recorded one, current() the one the world
// shows now. Going back (stepBack, seek) only moves the cursor, so the later
// entries stay and can be scrubbed to again; recording a new step from an earlier
// entry (push) first discards every entry after the cursor, as typing after an
// undo discards the redo. When full (capacity() entries, or more than byteBudget()
// bytes of packed traces and snapshots, warm-start caches included), push drops the oldest entries: a scene with
// many bodies keeps fewer steps (fifty boxes 400), a small one all 1000, so the
// app stays within its memory target (docs/performance.md).
#pragma once

#include "app/core/compact_trace.h"
#include "physics/engine/world.h"

#include <cstddef>
#include <deque>

namespace rbw {

struct HistoryEntry {
    WorldSnapshot state;   // the world after the step
    CompactTrace trace;    // that step's trace, packed (empty for the initial state)
    bool hasTrace = false;

    std::size_t bytes() const
    {
        // WorldSnapshot::bytes() counts everything a step carries over: body states,
        // torque switches, and the manifold model's warm-start cache and sleep state.
        return sizeof(HistoryEntry) + trace.bytes() + state.bytes();
    }
};

class StepHistory {
public:
    // 1001 states: the current one and the 1000 before it.
    static constexpr std::size_t kDefaultCapacity = 1001;
    // At most 48 MiB of packed history (lesson 4's six boxes: 12 MB for 1000
    // steps; the fifty-box variant about 125 kB a step).
    static constexpr std::size_t kDefaultByteBudget = std::size_t(48) << 20;

    explicit StepHistory(std::size_t capacity = kDefaultCapacity, std::size_t byteBudget = kDefaultByteBudget)
        : capacity_(capacity < 2 ? 2 : capacity), byteBudget_(byteBudget)
    {
    }

    std::size_t capacity() const { return capacity_; }
    std::size_t byteBudget() const { return byteBudget_; }
    // The bytes the kept entries take (HistoryEntry::bytes()).
    std::size_t bytes() const { return bytes_; }
    std::size_t size() const { return entries_.size(); }
    bool empty() const { return entries_.empty(); }
    void clear()
    {
        entries_.clear();
        cursor_ = 0;
        bytes_ = 0;
    }

    // Discards the entries after the cursor, appends the new one and makes it current.
    void push(HistoryEntry entry)
    {
        discardAfterCursor();
        const std::size_t added = entry.bytes();
        // Keep at least the new entry and the one before it (Step back).
        while (!entries_.empty() && (entries_.size() >= capacity_ || bytes_ + added > byteBudget_) &&
               entries_.size() >= 2) {
            bytes_ -= entries_.front().bytes();
            entries_.pop_front();
        }
        if (entries_.size() >= capacity_) {
            bytes_ -= entries_.front().bytes();
            entries_.pop_front();
        }
        entries_.push_back(std::move(entry));
        bytes_ += added;
        cursor_ = entries_.size() - 1;
    }

    // Drops every entry after the current one (the "redo" part). Returns how many went.
    std::size_t discardAfterCursor()
    {
        const std::size_t keep = entries_.empty() ? 0 : cursor_ + 1;
        const std::size_t dropped = entries_.size() - keep;
        while (entries_.size() > keep) {
            bytes_ -= entries_.back().bytes();
            entries_.pop_back();
        }
        return dropped;
    }

    // Moves the cursor one entry back; false if it is at the oldest entry (or empty).
    bool pop()
    {
        if (entries_.empty() || cursor_ == 0) {
            return false;
        }
        --cursor_;
        return true;
    }

    // Makes entry i current (i < size()); false (nothing changes) if out of range.
    bool seek(std::size_t i)
    {
        if (i >= entries_.size()) {
            return false;
        }
        cursor_ = i;
        return true;
    }

    // The entry the world shows now.
    const HistoryEntry& current() const { return entries_.at(cursor_); }
    std::size_t cursor() const { return cursor_; }
    // The newest recorded entry (current() unless the cursor went back).
    const HistoryEntry& last() const { return entries_.back(); }
    const HistoryEntry& back() const { return last(); }
    // Entry i, 0 being the oldest kept (i < size()).
    const HistoryEntry& at(std::size_t i) const { return entries_.at(i); }
    // How many steps back are possible from here.
    std::size_t stepsBackAvailable() const { return entries_.empty() ? 0 : cursor_; }
    // How many recorded steps lie after the current one.
    std::size_t stepsForwardAvailable() const { return entries_.empty() ? 0 : entries_.size() - 1 - cursor_; }
    // The step index k of the oldest and newest kept states (the world's stepIndex()).
    long firstStep() const { return entries_.empty() ? 0 : entries_.front().state.stepIndex; }
    long lastStep() const { return entries_.empty() ? 0 : entries_.back().state.stepIndex; }
    // The entry whose state has step index k, or -1 if it is not kept. The step
    // indices of consecutive entries differ by one.
    long indexOfStep(long k) const
    {
        if (entries_.empty() || k < firstStep() || k > lastStep()) {
            return -1;
        }
        return k - firstStep();
    }

private:
    std::size_t capacity_;
    std::size_t byteBudget_;
    std::size_t bytes_ = 0;
    std::deque<HistoryEntry> entries_;
    std::size_t cursor_ = 0;
};

} // namespace rbw
