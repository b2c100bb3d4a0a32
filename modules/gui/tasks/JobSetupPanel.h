// The job setup task panel (docked like the operations' panels): the job's model (Import), stock
// (box from the model's bounds with offsets, explicit box, cylinder, or a blank from a file), work coordinate system
// (origin on a stock corner/centre, on a model vertex picked in the view, Z0 on a face picked there, or typed;
// G54…G59), machine (its travels checked against the stock), post and its properties (PostPropertiesForm), and the NC
// output's name and folder. It edits a copy of the job; OK applies it as one undoable step, Cancel changes nothing.
#pragma once

#include "base/Vec.h"
#include "document/Job.h"
#include "kinematics/Machine.h"
#include "post/PostInfo.h"

#include <QWidget>

#include <array>
#include <optional>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QScrollArea;

namespace camwb::gui {

class PostPropertiesForm;
class TaskOverlay;
class Workbench;

class JobSetupPanel : public QWidget {
    Q_OBJECT
public:
    // `overlay` (may be null) offers the vertex picked in the 3D view as the origin, and the face
    // picked there as its Z level.
    JobSetupPanel(Workbench& workbench, TaskOverlay* overlay, QWidget* parent = nullptr);

    // The job as OK would make it (only its setup fields differ from the Workbench's job).
    const document::Job& setup() const { return m_setup; }
    // The post's properties form (the same as Post Settings'), inside "postPropertiesSlot".
    PostPropertiesForm* postProperties() const { return m_postProperties; }

    // OK: applies (one undo step, none when nothing changed) and closes; false, the panel staying,
    // when the stock is no box (document::stockProblem, said in the panel) or the post cannot load.
    bool accept();
    void reject();  // Cancel: changes nothing and closes
    bool hasUnappliedChanges() const;
    // The stock becomes the blank in `path` (a mesh or STEP file, in the model's coordinates), its
    // box the blank's bounds; false (said in the panel, nothing changed) when it cannot be read.
    // "Blank from file…" and Choose… ask for the file and come here.
    bool setBlankFile(const QString& path);

signals:
    void closed();
    void importRequested();  // the Import button: the window runs Cam.File.ImportModel

private:
    using Vec3Fields = std::array<QDoubleSpinBox*, 3>;

    QWidget* buildModel();
    QWidget* buildStock();
    QWidget* buildWcs();
    QWidget* buildMachine();
    QWidget* buildPost();
    QWidget* buildOutput();
    Vec3Fields vec3Fields(const char* objectName, double min, double max);
    // A red, wrapping line that says what is wrong; hidden until there is something to say.
    static QLabel* warningLabel(const char* objectName);

    // The model's bounds in the coordinates of the file (the origin not applied); none without a model.
    bool modelBounds(base::Vec3& min, base::Vec3& max) const;
    void stockEdited();
    void originEdited();
    // Moves the origin by `delta` (model coordinates): an explicit stock stays where it is.
    void moveOrigin(const base::Vec3& delta);
    void resolveStock();
    void stockMoved();  // after a change of the stock: an origin on it follows, the fields show it
    void chooseBlankFile();
    void showStock();
    void showValues();  // writes m_setup into the fields (signals blocked)
    void checkTravels();
    void originOnPickedFace();
    void originOnPickedVertex();
    void switchPostTo(int index);
    void fitWidth();
    void fitWidthNow();
    void nameWorkOffsets();
    void filterPosts();
    void finish();

    Workbench& m_workbench;
    TaskOverlay* m_overlay;
    document::Job m_original;
    document::Job m_setup;
    bool m_showing = false;  // showValues() is writing the fields
    bool m_finished = false;

    QLabel* m_modelLabel = nullptr;
    QComboBox* m_stockShape = nullptr;
    QComboBox* m_stockSize = nullptr;
    Vec3Fields m_below{}, m_above{}, m_min{}, m_max{};
    QWidget* m_offsetRows = nullptr;
    QWidget* m_explicitRows = nullptr;
    QLabel* m_stockSummary = nullptr;
    QLabel* m_stockError = nullptr;  // document::stockProblem, which OK refuses
    QWidget* m_blankRow = nullptr;
    QLabel* m_blankLabel = nullptr;
    QLabel* m_blankError = nullptr;
    QComboBox* m_originAnchor = nullptr;
    Vec3Fields m_origin{};
    QLabel* m_originNote = nullptr;
    QComboBox* m_workOffset = nullptr;
    QComboBox* m_machine = nullptr;
    QLabel* m_travelWarning = nullptr;
    QComboBox* m_post = nullptr;
    QLabel* m_postWarning = nullptr;
    std::vector<post::PostInfo> m_postInfos;             // by m_post's index
    std::optional<kinematics::Machine> m_chosenMachine;  // the machine chosen (none: the post's default)
    QScrollArea* m_scroll = nullptr;
    QWidget* m_postPropertiesSlot = nullptr;
    QLabel* m_postDropped = nullptr;
    PostPropertiesForm* m_postProperties = nullptr;
    QLineEdit* m_outputName = nullptr;
    QLineEdit* m_outputFolder = nullptr;
};

}  // namespace camwb::gui
