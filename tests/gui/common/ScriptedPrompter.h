// A Prompter for GUI tests: answers from queues the test fills and records every question, file
// request and error, so a test can check that a prompt came (or did not) and what it said. A
// question with no answer queued is answered Cancel (a file request: none), the safe answers.
#pragma once

#include "gui/shell/Prompter.h"

#include <QList>
#include <QString>
#include <QStringList>

#include <deque>

class ScriptedPrompter : public camwb::gui::Prompter {
public:
    std::deque<Answer> answers;
    std::deque<QString> files;  // for openFileName and saveFileName, in order
    QList<Question> questions;
    QStringList fileTitles;  // the title of every file request
    QStringList errors;
    int unanswered = 0;  // questions and file requests that found no answer queued

    Answer ask(const Question& question) override
    {
        questions << question;
        return next(answers, Answer::Cancel);
    }
    QString openFileName(const QString& title, const QString&) override
    {
        fileTitles << title;
        return next(files, QString());
    }
    QString saveFileName(const QString& title, const QString&, const QString&) override
    {
        fileTitles << title;
        return next(files, QString());
    }
    void showError(const QString& title, const QString& text) override
    {
        errors << title + QStringLiteral(": ") + text;
    }

private:
    template <class T> T next(std::deque<T>& queue, T safe)
    {
        if (queue.empty()) {
            ++unanswered;
            return safe;
        }
        T answer = queue.front();
        queue.pop_front();
        return answer;
    }
};
