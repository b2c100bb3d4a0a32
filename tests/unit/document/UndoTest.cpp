#include "document/JobDocument.h"
#include "document/UndoStack.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace camwb::document;

TEST(UndoStack, UndoRedoAndDroppedRedoHistory)
{
    int value = 0;
    struct Add : UndoCommand {
        int& v;
        int d;
        Add(int& v, int d) : v(v), d(d) {}
        void redo() override { v += d; }
        void undo() override { v -= d; }
        std::string text() const override { return "add " + std::to_string(d); }
    };
    UndoStack stack;
    stack.push(std::make_unique<Add>(value, 1));
    stack.push(std::make_unique<Add>(value, 10));
    EXPECT_EQ(value, 11);
    EXPECT_EQ(stack.undoText(), "add 10");
    stack.undo();
    EXPECT_EQ(value, 1);
    EXPECT_EQ(stack.redoText(), "add 10");
    stack.push(std::make_unique<Add>(value, 100));  // drops "add 10"
    EXPECT_FALSE(stack.canRedo());
    EXPECT_EQ(value, 101);
    stack.undo();
    stack.undo();
    EXPECT_EQ(value, 0);
    EXPECT_FALSE(stack.canUndo());
    stack.redo();
    EXPECT_EQ(value, 1);
}

TEST(UndoStack, CleanStateFollowsSaves)
{
    struct Nop : UndoCommand {
        void redo() override {}
        void undo() override {}
        std::string text() const override { return "nop"; }
    };
    UndoStack stack;
    EXPECT_TRUE(stack.isClean());
    stack.push(std::make_unique<Nop>());
    EXPECT_FALSE(stack.isClean());
    stack.setClean();
    EXPECT_TRUE(stack.isClean());
    stack.undo();
    EXPECT_FALSE(stack.isClean());
    stack.redo();
    EXPECT_TRUE(stack.isClean());
    stack.undo();
    stack.push(std::make_unique<Nop>());  // the saved state is gone from the history
    stack.undo();
    stack.redo();
    EXPECT_FALSE(stack.isClean());
}

TEST(JobDocument, EveryEditIsOneUndoableStepAndNotifies)
{
    JobDocument doc;
    int notifications = 0;
    doc.setChangedListener([&] { ++notifications; });
    Job job;
    job.name = "A";
    doc.reset(job, "");
    EXPECT_EQ(notifications, 1);
    EXPECT_FALSE(doc.isModified());

    doc.edit("rename", [](Job& j) { j.name = "B"; });
    doc.edit("offset", [](Job& j) { j.workOffset = 3; });
    EXPECT_EQ(notifications, 3);
    EXPECT_TRUE(doc.isModified());
    EXPECT_EQ(doc.job().name, "B");

    doc.undo();
    EXPECT_EQ(doc.job().workOffset, 1);
    EXPECT_EQ(doc.job().name, "B");
    doc.undo();
    EXPECT_EQ(doc.job().name, "A");
    EXPECT_FALSE(doc.isModified());
    doc.redo();
    EXPECT_EQ(doc.job().name, "B");
    EXPECT_EQ(notifications, 6);
}

TEST(JobDocument, ReplaceWithTheSameJobAddsNoStep)
{
    JobDocument doc;
    Job job;
    job.name = "A";
    doc.reset(job, "");
    EXPECT_FALSE(doc.replace("same", job));
    EXPECT_EQ(doc.undoStack().count(), 0u);
    EXPECT_FALSE(doc.isModified());
    job.workOffset = 2;
    EXPECT_TRUE(doc.replace("offset", job));
    EXPECT_EQ(doc.undoStack().count(), 1u);
    EXPECT_EQ(doc.undoStack().undoText(), "offset");
    EXPECT_EQ(doc.job().workOffset, 2);
    doc.undo();
    EXPECT_EQ(doc.job().workOffset, 1);
}

TEST(JobDocument, SaveMakesCleanAndFailedSaveKeepsState)
{
    const auto dir = std::filesystem::temp_directory_path() / "camwb-jobdoc-test";
    std::filesystem::create_directories(dir);
    JobDocument doc;
    doc.reset(Job{}, "");
    doc.edit("rename", [](Job& j) { j.name = "Saved"; });
    EXPECT_FALSE(doc.saveAs((dir / "missing-folder" / "x.camwb").string()));
    EXPECT_TRUE(doc.isModified());
    EXPECT_EQ(doc.path(), "");
    ASSERT_TRUE(doc.saveAs((dir / "x.camwb").string()));
    EXPECT_FALSE(doc.isModified());
    EXPECT_EQ(doc.path(), (dir / "x.camwb").string());
    std::filesystem::remove_all(dir);
}

TEST(JobDocument, ListenersSeeTheStackInItsNewState)
{
    JobDocument doc;
    doc.reset(Job{}, "");
    std::vector<std::pair<bool, bool>> seen;  // canUndo, canRedo at each notification
    doc.setChangedListener([&] { seen.emplace_back(doc.undoStack().canUndo(), doc.undoStack().canRedo()); });
    doc.edit("rename", [](Job& j) { j.name = "B"; });
    doc.undo();
    doc.redo();
    ASSERT_EQ(seen.size(), 3u);
    EXPECT_EQ(seen[0], std::make_pair(true, false));
    EXPECT_EQ(seen[1], std::make_pair(false, true));
    EXPECT_EQ(seen[2], std::make_pair(true, false));
}
