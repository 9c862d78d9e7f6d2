// Undo and redo as whole states (the viewer's edit states are a few prims' descriptions):
// an edit pushes the state before it and forgets what could be redone; undo hands back the
// state before the last edit and keeps the current one for redo. At most `limit` states
// are kept (the oldest go first).
#pragma once

#include <cstddef>
#include <deque>
#include <optional>
#include <utility>

namespace opal::view {

template <class State>
class UndoStack {
public:
    explicit UndoStack(std::size_t limit = 256) : limit_(limit) {}

    // The state before an edit.
    void push(State before) {
        undo_.push_back(std::move(before));
        if (undo_.size() > limit_) undo_.pop_front();
        redo_.clear();
    }
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }

    // The state to go back to (nothing when there is none); `current` becomes redoable.
    std::optional<State> undo(State current) { return move(undo_, redo_, std::move(current)); }
    // The state undo left (nothing when there is none); `current` becomes undoable.
    std::optional<State> redo(State current) { return move(redo_, undo_, std::move(current)); }

    void clear() {
        undo_.clear();
        redo_.clear();
    }

private:
    static std::optional<State> move(std::deque<State>& from, std::deque<State>& to, State current) {
        if (from.empty()) return std::nullopt;
        State state = std::move(from.back());
        from.pop_back();
        to.push_back(std::move(current));
        return state;
    }

    std::size_t limit_;
    std::deque<State> undo_, redo_;
};

}  // namespace opal::view
