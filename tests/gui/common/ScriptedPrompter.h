// A Prompter for GUI tests: answers from queues the test fills and records every question, so a
// test can check that a prompt came (or did not) and what it said. A question with no answer
// queued gets the safe answer (Cancel, false, no file) and counts as unexpected.
#pragma once

#include "gui/shell/Prompter.h"

#include <QList>
#include <QString>

#include <deque>

class ScriptedPrompter : public camwb::gui::Prompter {
public:
    enum class Kind { SaveChanges, Confirm, OpenFile, SaveFile };
    struct Question {
        Kind kind;
        QString title;
        QString text;
    };

    std::deque<camwb::gui::SaveChoice> saveAnswers;
    std::deque<bool> confirmAnswers;
    std::deque<QString> fileAnswers;  // for both openFileName and saveFileName, in order
    QList<Question> asked;
    int unexpected = 0;

    int count(Kind kind) const
    {
        int n = 0;
        for (const Question& q : asked)
            n += q.kind == kind ? 1 : 0;
        return n;
    }

    camwb::gui::SaveChoice askSaveChanges(QWidget*, const QString& title, const QString& text) override
    {
        asked.append({Kind::SaveChanges, title, text});
        return next(saveAnswers, camwb::gui::SaveChoice::Cancel);
    }
    bool confirm(QWidget*, const QString& title, const QString& text) override
    {
        asked.append({Kind::Confirm, title, text});
        return next(confirmAnswers, false);
    }
    QString openFileName(QWidget*, const QString& caption, const QString&, const QString&) override
    {
        asked.append({Kind::OpenFile, caption, {}});
        return next(fileAnswers, QString());
    }
    QString saveFileName(QWidget*, const QString& caption, const QString& suggested, const QString&) override
    {
        asked.append({Kind::SaveFile, caption, suggested});
        return next(fileAnswers, QString());
    }

private:
    template <class T> T next(std::deque<T>& answers, T safe)
    {
        if (answers.empty()) {
            ++unexpected;
            return safe;
        }
        T answer = answers.front();
        answers.pop_front();
        return answer;
    }
};
