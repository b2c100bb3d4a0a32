// The form of a post's typed properties (post::PostInfo::properties), one row each: a check box,
// combo, spin box or line edit, the title as label, the description as tooltip, the default beside
// it and a reset button; values that differ from the default are bold. Self-contained, so the post
// settings panel and the job setup panel embed the same form.
#pragma once

#include "post/PostInfo.h"

#include <QString>
#include <QWidget>

#include <map>
#include <string>
#include <vector>

class QGridLayout;
class QLabel;
class QToolButton;

namespace camwb::gui {

class PostPropertiesForm : public QWidget {
    Q_OBJECT
public:
    explicit PostPropertiesForm(QWidget* parent = nullptr);

    // Rebuilds the rows for `info`'s properties showing `values` (text by name, as in the job's
    // postProperties); a name the post lacks or a value it refuses shows the default instead.
    void setPost(const post::PostInfo& info, const std::map<std::string, std::string>& values);
    const post::PostInfo& post() const { return m_info; }
    // Compact (for a narrow task panel): no column with each default, which goes into the
    // tooltip instead. Takes effect at the next setPost.
    void setCompact(bool compact) { m_compact = compact; }
    // The values that differ from their defaults, as canonical text by name (the job's map).
    std::map<std::string, std::string> values() const;
    // What the form shows for `name`, as canonical text (empty for an unknown name).
    std::string value(const std::string& name) const;
    void resetToDefault(const std::string& name);
    // The editor of `name` (object name "property.<name>"), nullptr when unknown: for tests.
    QWidget* editor(const std::string& name) const;

signals:
    void changed();

private:
    struct Row {
        const post::PropertyDef* def = nullptr;
        QLabel* label = nullptr;
        QWidget* editor = nullptr;
        QToolButton* reset = nullptr;
    };
    void addRow(const post::PropertyDef& def, const std::string& value, int gridRow);
    void show(const Row& row, const std::string& value);
    void edited(const Row& row);
    void markDefault(const Row& row);
    const Row* row(const std::string& name) const;

    post::PostInfo m_info;
    std::vector<Row> m_rows;
    QGridLayout* m_grid = nullptr;
    QLabel* m_empty = nullptr;
    bool m_showing = false;
    bool m_compact = false;  // setting editors: their signals are not the user's edits
};

}  // namespace camwb::gui
