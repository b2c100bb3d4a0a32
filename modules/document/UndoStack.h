// Undo/redo without Qt: commands know how to undo and redo themselves; the stack tracks the
// clean state (saved to disk). The GUI binds its Undo/Redo actions to a stack of this type.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace camwb::document {

class UndoCommand {
public:
    virtual ~UndoCommand() = default;
    virtual void redo() = 0;
    virtual void undo() = 0;
    virtual std::string text() const = 0;
};

class UndoStack {
public:
    // Runs command->redo() and makes it the newest undoable step; drops any redo history.
    void push(std::unique_ptr<UndoCommand> command);
    bool canUndo() const { return m_index > 0; }
    bool canRedo() const { return m_index < m_commands.size(); }
    void undo();
    void redo();
    std::string undoText() const;
    std::string redoText() const;
    std::size_t count() const { return m_commands.size(); }
    void clear();
    bool isClean() const { return m_cleanIndex == static_cast<long>(m_index); }
    void setClean() { m_cleanIndex = static_cast<long>(m_index); }

private:
    std::vector<std::unique_ptr<UndoCommand>> m_commands;
    std::size_t m_index = 0;  // commands before this index are done
    long m_cleanIndex = 0;    // -1 when the clean state was dropped from the history
};

}  // namespace camwb::document
