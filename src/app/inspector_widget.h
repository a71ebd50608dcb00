#pragma once
// The Inspector: the selected object's rotation mode (quaternion or Euler, and its Euler convention, set by
// SetRotationModeCommand), and the selected keyframe of the selected object, its time, constraint flag, position
// and orientation, the orientation shown at once as a quaternion, a rotation matrix, an axis-angle
// and three Euler angles in a chosen convention, each editable. An edit becomes one undo command on
// the document, and every field then reads the key back from the document, so the representations
// always agree. In Euler mode the angle fields come first and show the angles the key stores, as typed (720° is
// two turns). Near gimbal lock of the chosen convention a warning says which angles lost meaning.

#include "app/number_fields.h"
#include "app/selected_track.h"
#include "app/selection.h"
#include "app/view_refresh.h"
#include "core/euler_angles.h"
#include "model/document.h"

#include <Eigen/Geometry>
#include <QStyle>
#include <QWidget>

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace Ui {
class InspectorWidget;
}

namespace gyre::app {

class InspectorWidget : public QWidget {
    Q_OBJECT

public:
    InspectorWidget(model::Document& document, Selection& selection, QWidget* parent = nullptr);
    ~InspectorWidget() override;

private:
    // The numbers last typed into one rotation representation and the rotation the document stored
    // from them. While the key keeps exactly that rotation the representation shows the numbers as
    // typed, not converted back: typing 90° shows 90, not 89.99999999999999.
    struct TypedRotation {
        model::ObjectId object = model::kNoObject;
        std::size_t key = 0;
        const NumberFields* fields = nullptr;
        EulerConvention convention;  // of the Euler angles; unused for the other representations
        std::vector<double> values;
        Eigen::Quaterniond stored = Eigen::Quaterniond::Identity();
    };

    void setUpConventionChoosers();
    EulerConvention chosenConvention() const;
    void updateEulerLabels();
    void showSelectedKey();
    // The object's rotation mode in the choosers, and in Euler mode the angle fields first.
    void showRotationMode(const model::SceneObject* object);
    void applyRotationMode();
    void showOrientation(const model::SceneObject& object, std::size_t keyIndex);
    void showNoKey();
    void setKeyFieldsEnabled(bool enabled);

    // The keyframe the fields show, which edits go to.
    const model::Keyframe& shownKeyframe() const;
    // Runs `edit`; if the edit is refused (std::invalid_argument, from a field that is not a number or
    // from a command), shows `refusal` with the reason in place of %1.
    void tryEdit(const QString& refusal, const std::function<void()>& edit);
    void applyTime();
    void applyConstraint(bool constrained);
    void applyPosition();
    void applyQuaternion();
    void applyMatrix();
    void applyAxisAngle();
    void applyEulerAngles();
    // Gives the shown key `orientation`, made from numbers typed into `fields`; `exactlyTyped` are
    // those numbers if they are an exact rotation, to be shown back as typed. `adjustment` says how
    // the typed value was made a rotation, or is empty.
    void setOrientation(const NumberFields& fields, const std::optional<std::vector<double>>& exactlyTyped,
                        const Eigen::Quaterniond& orientation, const QString& adjustment);

    // A message above the fields, with the style's icon for its kind, until the next edit or selection.
    void showMessage(QStyle::StandardPixmap icon, const QString& message);
    void showError(const QString& message) { showMessage(QStyle::SP_MessageBoxCritical, message); }
    void showNotice(const QString& message) { showMessage(QStyle::SP_MessageBoxInformation, message); }
    void clearMessage();

    std::unique_ptr<Ui::InspectorWidget> ui_;
    model::Document& document_;
    Selection& selection_;
    SelectedTrack selectedTrack_;
    // The fields follow the selected track while the form is on screen, and catch up when it is back.
    ViewRefresh refresh_;
    // The key the fields show, which edits go to.
    model::ObjectId shownObject_ = model::kNoObject;
    std::optional<std::size_t> shownKey_;
    NumberFields* time_ = nullptr;
    NumberFields* position_ = nullptr;
    NumberFields* quaternion_ = nullptr;
    NumberFields* matrix_ = nullptr;
    NumberFields* axisAngle_ = nullptr;
    NumberFields* eulerAngles_ = nullptr;
    std::optional<TypedRotation> typedRotation_;
    // The object and rotation mode the Rotation Mode choosers were last set to.
    std::pair<model::ObjectId, model::RotationMode> modeShown_{model::kNoObject, {}};
};

} // namespace gyre::app
