#include "document/UndoStack.h"

namespace camwb::document {

void UndoStack::push(std::unique_ptr<UndoCommand> command)
{
    if (m_cleanIndex > static_cast<long>(m_index))
        m_cleanIndex = -1;  // the saved state was in the redo history we are dropping
    m_commands.resize(m_index);
    m_commands.push_back(std::move(command));
    ++m_index;
    // Run it only now, so that whoever it notifies already sees it as undoable.
    m_commands.back()->redo();
}

void UndoStack::undo()
{
    if (!canUndo())
        return;
    --m_index;
    m_commands[m_index]->undo();  // the stack is already in its new state when listeners hear of it
}

void UndoStack::redo()
{
    if (!canRedo())
        return;
    ++m_index;
    m_commands[m_index - 1]->redo();
}

std::string UndoStack::undoText() const { return canUndo() ? m_commands[m_index - 1]->text() : std::string(); }
std::string UndoStack::redoText() const { return canRedo() ? m_commands[m_index]->text() : std::string(); }

void UndoStack::clear()
{
    m_commands.clear();
    m_index = 0;
    m_cleanIndex = 0;
}

}  // namespace camwb::document
