// The Inspector driven as the artist drives it: typing into its fields and pressing Enter, choosing
// an Euler convention, clicking the constraint. Each edit is checked against a rotation built here
// independently (products of Eigen::AngleAxisd, DESIGN.md's convention), against the other
// representations the panel then shows, and against the undo stack.

#include "inspected_window.h"

#include "gui_test_support.h"
#include "model/commands/set_mass_override_command.h"
#include "model/object_mass.h"

#include <QCheckBox>
#include <QFrame>
#include <QLabel>
#include <QScrollArea>
#include <QTest>

#include <cmath>
#include <numbers>
#include <utility>

using namespace gyre;
using test::enter;
using test::InspectedWindow;
using test::shownNumber;
using test::typeOver;

namespace {

// The sample's keyframe 2: a quarter turn about z at (4, 2, 0), two seconds in.
constexpr std::size_t kQuarterTurnKey = 2;

constexpr double kShownTolerance = 1e-6; // the fields show six places

double radians(double degrees)
{
    return degrees * std::numbers::pi / 180.0;
}

Eigen::Quaterniond about(const Eigen::Vector3d& axis, double degrees)
{
    return Eigen::Quaterniond(Eigen::AngleAxisd(radians(degrees), axis));
}

bool sameRotation(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
    return a.angularDistance(b) < 1e-12;
}

// The panel shows `expected` in its quaternion (up to sign), matrix and axis-angle fields.
void checkRepresentations(InspectedWindow& inspected, const Eigen::Quaterniond& expected)
{
    Eigen::Quaterniond shown(shownNumber(inspected.field("quaternionWEdit")),
                             shownNumber(inspected.field("quaternionXEdit")),
                             shownNumber(inspected.field("quaternionYEdit")),
                             shownNumber(inspected.field("quaternionZEdit")));
    if (shown.dot(expected) < 0.0)
        shown.coeffs() = -shown.coeffs();
    QVERIFY((shown.coeffs() - expected.coeffs()).cwiseAbs().maxCoeff() < kShownTolerance);

    const Eigen::Matrix3d matrix = expected.toRotationMatrix();
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column) {
            const QByteArray name = QStringLiteral("matrix%1%2Edit").arg(row).arg(column).toLatin1();
            QVERIFY(std::abs(shownNumber(inspected.field(name.constData())) - matrix(row, column)) < kShownTolerance);
        }
    }

    const Eigen::AngleAxisd axisAngle(expected);
    const Eigen::Vector3d shownAxis(shownNumber(inspected.field("axisXEdit")), shownNumber(inspected.field("axisYEdit")),
                                    shownNumber(inspected.field("axisZEdit")));
    QVERIFY((shownAxis - axisAngle.axis()).cwiseAbs().maxCoeff() < kShownTolerance);
    QVERIFY(std::abs(shownNumber(inspected.field("angleEdit")) - axisAngle.angle() * 180.0 / std::numbers::pi) <
            kShownTolerance);
}

} // namespace

class TestInspector : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void showsTheSelectedKeyInEveryRepresentation()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        QCOMPARE(inspected.field("timeEdit")->text(), QStringLiteral("2"));
        QCOMPARE(inspected.field("positionXEdit")->text(), QStringLiteral("4"));
        QCOMPARE(inspected.field("positionYEdit")->text(), QStringLiteral("2"));
        QCOMPARE(inspected.field("positionZEdit")->text(), QStringLiteral("0"));
        QVERIFY(inspected.child<QCheckBox>("constrainedCheck")->isChecked());
        QCOMPARE(inspected.field("quaternionWEdit")->text(), QStringLiteral("0.707107"));
        checkRepresentations(inspected, about(Eigen::Vector3d::UnitZ(), 90.0));
        // Extrinsic xyz by default: no turn about x or y, a quarter turn about z.
        QCOMPARE(inspected.field("euler1Edit")->text(), QStringLiteral("0"));
        QCOMPARE(inspected.field("euler2Edit")->text(), QStringLiteral("0"));
        QCOMPARE(inspected.field("euler3Edit")->text(), QStringLiteral("90"));
        QVERIFY(inspected.child<QLabel>("noKeyLabel")->isHidden());
    }

    void withoutASelectedKeyThePanelSaysSoAndItsFieldsAreDisabled()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        inspected.window().selection().selectObject(inspected.object());
        QVERIFY(!inspected.child<QLabel>("noKeyLabel")->isHidden());
        QVERIFY(!inspected.field("euler1Edit")->isEnabled());
        QVERIFY(!inspected.child<QCheckBox>("constrainedCheck")->isEnabled());
        QVERIFY(inspected.field("quaternionWEdit")->text().isEmpty());
        QVERIFY(inspected.child<QFrame>("gimbalWarningFrame")->isHidden());
    }

    void typedEulerAnglesAreOneUndoStepThatUndoAndRedoFollow()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const Eigen::Quaterniond before = inspected.key(kQuarterTurnKey).pose.orientation;
        const int steps = inspected.undoSteps();

        // Moving between the three angles applies nothing; Enter applies all three at once.
        typeOver(inspected.field("euler1Edit"), QStringLiteral("30"));
        typeOver(inspected.field("euler2Edit"), QStringLiteral("45"));
        QCOMPARE(inspected.undoSteps(), steps);
        enter(inspected.field("euler3Edit"), QStringLiteral("60"));

        // Extrinsic xyz: R = Rz(e3)·Ry(e2)·Rx(e1).
        const Eigen::Quaterniond expected =
            about(Eigen::Vector3d::UnitZ(), 60.0) * about(Eigen::Vector3d::UnitY(), 45.0) * about(Eigen::Vector3d::UnitX(), 30.0);
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, expected));
        QCOMPARE(inspected.undoSteps(), steps + 1);
        checkRepresentations(inspected, expected);
        // The angles read back are the ones typed, to the last bit.
        QCOMPARE(inspected.field("euler1Edit")->text(), QStringLiteral("30"));
        QCOMPARE(inspected.field("euler2Edit")->text(), QStringLiteral("45"));
        QCOMPARE(inspected.field("euler3Edit")->text(), QStringLiteral("60"));
        QCOMPARE(inspected.field("euler3Edit")->toolTip(), QStringLiteral("Exact value: 60"));

        QUndoStack& stack = inspected.window().document().undoStack();
        stack.undo();
        QCOMPARE(inspected.key(kQuarterTurnKey).pose.orientation.coeffs(), before.coeffs());
        QCOMPARE(inspected.field("euler3Edit")->text(), QStringLiteral("90"));
        checkRepresentations(inspected, before);
        stack.redo();
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, expected));
        QCOMPARE(inspected.field("euler1Edit")->text(), QStringLiteral("30"));
        checkRepresentations(inspected, expected);
    }

    void theConventionChoosersChangeWhatTheAnglesMean()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        QTest::keyClicks(inspected.child<QComboBox>("eulerOrderCombo"), QStringLiteral("ZYX"));
        QCOMPARE(inspected.child<QComboBox>("eulerOrderCombo")->currentText(), QStringLiteral("ZYX"));
        QTest::keyClick(inspected.child<QComboBox>("eulerFrameCombo"), Qt::Key_Down);
        QCOMPARE(inspected.child<QComboBox>("eulerFrameCombo")->currentIndex(), 1);
        QCOMPARE(inspected.child<QLabel>("euler1Label")->text(), QStringLiteral("about z (°)"));
        // The quarter turn about z is the first angle of zyx.
        QCOMPARE(inspected.field("euler1Edit")->text(), QStringLiteral("90"));

        typeOver(inspected.field("euler1Edit"), QStringLiteral("-20"));
        typeOver(inspected.field("euler2Edit"), QStringLiteral("70"));
        enter(inspected.field("euler3Edit"), QStringLiteral("135"));
        // Intrinsic zyx: R = Rz(e1)·Ry(e2)·Rx(e3).
        const Eigen::Quaterniond expected = about(Eigen::Vector3d::UnitZ(), -20.0) *
                                            about(Eigen::Vector3d::UnitY(), 70.0) * about(Eigen::Vector3d::UnitX(), 135.0);
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, expected));
        checkRepresentations(inspected, expected);
    }

    void aTypedQuaternionIsStoredAsTypedOrScaledToUnitLengthWithANotice()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const int steps = inspected.undoSteps();
        typeOver(inspected.field("quaternionWEdit"), QStringLiteral("0"));
        typeOver(inspected.field("quaternionXEdit"), QStringLiteral("1"));
        enter(inspected.field("quaternionZEdit"), QStringLiteral("0"));
        QCOMPARE(inspected.key(kQuarterTurnKey).pose.orientation.coeffs(), Eigen::Quaterniond(0, 1, 0, 0).coeffs());
        QCOMPARE(inspected.undoSteps(), steps + 1);
        QCOMPARE(inspected.field("euler1Edit")->text(), QStringLiteral("180"));
        checkRepresentations(inspected, Eigen::Quaterniond(0, 1, 0, 0));
        QVERIFY(inspected.child<QFrame>("inspectorMessageFrame")->isHidden());

        // (1, 0, 1, 0) has length √2: it means the rotation of (1, 0, 1, 0)/√2, a quarter turn about y.
        typeOver(inspected.field("quaternionWEdit"), QStringLiteral("1"));
        typeOver(inspected.field("quaternionXEdit"), QStringLiteral("0"));
        enter(inspected.field("quaternionYEdit"), QStringLiteral("1"));
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, about(Eigen::Vector3d::UnitY(), 90.0)));
        QCOMPARE(inspected.undoSteps(), steps + 2);
        QVERIFY(!inspected.child<QFrame>("inspectorMessageFrame")->isHidden());
        QVERIFY(inspected.child<QLabel>("inspectorMessageLabel")->text().contains(QStringLiteral("scaled to length 1")));
    }

    void aZeroQuaternionOrAxisOrANonNumberIsRefusedWithAMessage()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const Eigen::Quaterniond before = inspected.key(kQuarterTurnKey).pose.orientation;
        const int steps = inspected.undoSteps();
        QLabel* message = inspected.child<QLabel>("inspectorMessageLabel");

        typeOver(inspected.field("quaternionWEdit"), QStringLiteral("0"));
        enter(inspected.field("quaternionZEdit"), QStringLiteral("0"));
        QVERIFY(message->text().contains(QStringLiteral("zero quaternion")));

        typeOver(inspected.field("axisXEdit"), QStringLiteral("0"));
        typeOver(inspected.field("axisYEdit"), QStringLiteral("0"));
        enter(inspected.field("axisZEdit"), QStringLiteral("0"));
        QVERIFY(message->text().contains(QStringLiteral("zero axis")));

        enter(inspected.field("euler2Edit"), QStringLiteral("ninety"));
        QVERIFY(message->text().contains(QStringLiteral("second angle")));
        QVERIFY(message->text().contains(QStringLiteral("not a number")));

        QVERIFY(!inspected.child<QFrame>("inspectorMessageFrame")->isHidden());
        QCOMPARE(inspected.key(kQuarterTurnKey).pose.orientation.coeffs(), before.coeffs());
        QCOMPARE(inspected.undoSteps(), steps);
    }

    void aTypedAxisAngleTurnsTheKey()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        typeOver(inspected.field("axisXEdit"), QStringLiteral("1"));
        typeOver(inspected.field("axisYEdit"), QStringLiteral("0"));
        typeOver(inspected.field("axisZEdit"), QStringLiteral("0"));
        enter(inspected.field("angleEdit"), QStringLiteral("90"));
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, about(Eigen::Vector3d::UnitX(), 90.0)));
        QCOMPARE(inspected.field("angleEdit")->text(), QStringLiteral("90"));
        QCOMPARE(inspected.field("angleEdit")->toolTip(), QStringLiteral("Exact value: 90"));
        QCOMPARE(inspected.field("euler1Edit")->text(), QStringLiteral("90"));
    }

    void aTypedRotationMatrixIsOneStepAndANonRotationIsProjectedOrRefused()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const int steps = inspected.undoSteps();
        // A quarter turn about x: its columns are x, z and −y.
        const char* const names[] = {"matrix00Edit", "matrix01Edit", "matrix02Edit", "matrix10Edit", "matrix11Edit",
                                     "matrix12Edit", "matrix20Edit", "matrix21Edit", "matrix22Edit"};
        const char* const quarterTurnAboutX[] = {"1", "0", "0", "0", "0", "-1", "0", "1", "0"};
        for (int i = 0; i < 8; ++i)
            typeOver(inspected.field(names[i]), QString::fromLatin1(quarterTurnAboutX[i]));
        QCOMPARE(inspected.undoSteps(), steps);
        enter(inspected.field(names[8]), QString::fromLatin1(quarterTurnAboutX[8]));
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, about(Eigen::Vector3d::UnitX(), 90.0)));
        QCOMPARE(inspected.undoSteps(), steps + 1);
        checkRepresentations(inspected, about(Eigen::Vector3d::UnitX(), 90.0));
        QVERIFY(inspected.child<QFrame>("inspectorMessageFrame")->isHidden());

        // Stretching x is no rotation; the nearest rotation keeps the quarter turn, and the panel says so.
        enter(inspected.field("matrix00Edit"), QStringLiteral("2"));
        QVERIFY(sameRotation(inspected.key(kQuarterTurnKey).pose.orientation, about(Eigen::Vector3d::UnitX(), 90.0)));
        QVERIFY(inspected.child<QLabel>("inspectorMessageLabel")->text().contains(QStringLiteral("nearest rotation")));
        QCOMPARE(inspected.field("matrix00Edit")->text(), QStringLiteral("1"));

        // A mirror has no nearest rotation worth guessing.
        const Eigen::Quaterniond before = inspected.key(kQuarterTurnKey).pose.orientation;
        const int stepsBefore = inspected.undoSteps();
        enter(inspected.field("matrix00Edit"), QStringLiteral("-1"));
        QVERIFY(inspected.child<QLabel>("inspectorMessageLabel")->text().contains(QStringLiteral("determinant")));
        QCOMPARE(inspected.key(kQuarterTurnKey).pose.orientation.coeffs(), before.coeffs());
        QCOMPARE(inspected.undoSteps(), stepsBefore);
    }

    void aTypedPositionIsOneUndoStep()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const int steps = inspected.undoSteps();
        typeOver(inspected.field("positionXEdit"), QStringLiteral("1.5"));
        enter(inspected.field("positionZEdit"), QStringLiteral("-0.25"));
        QCOMPARE(inspected.key(kQuarterTurnKey).pose.position, Eigen::Vector3d(1.5, 2.0, -0.25));
        QCOMPARE(inspected.undoSteps(), steps + 1);
        inspected.window().document().undoStack().undo();
        QCOMPARE(inspected.key(kQuarterTurnKey).pose.position, Eigen::Vector3d(4.0, 2.0, 0.0));
        QCOMPARE(inspected.field("positionXEdit")->text(), QStringLiteral("4"));
    }

    void aTypedTimeMovesTheKeyButNotPastItsNeighbours()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const int steps = inspected.undoSteps();
        enter(inspected.field("timeEdit"), QStringLiteral("2.5"));
        QCOMPARE(inspected.key(kQuarterTurnKey).time, 2.5);
        QCOMPARE(inspected.undoSteps(), steps + 1);

        // The next key is at 3 s.
        enter(inspected.field("timeEdit"), QStringLiteral("3.5"));
        QCOMPARE(inspected.key(kQuarterTurnKey).time, 2.5);
        QCOMPARE(inspected.undoSteps(), steps + 1);
        QVERIFY(!inspected.child<QFrame>("inspectorMessageFrame")->isHidden());
        QVERIFY(inspected.child<QLabel>("inspectorMessageLabel")->text().startsWith(QStringLiteral("The keyframe was not moved")));
    }

    void typedMassPropertiesAreUndoStepsAndABodyThatCannotBeIsRefused()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        model::Document& document = inspected.window().document();
        const MassProperties fromMesh = model::objectMassProperties(*document.object(inspected.object())).properties;
        QLineEdit* mass = inspected.field("massEdit");
        // Below the key's groups: the artist scrolls down to it, and it shows the object once in view.
        auto* scrollArea = inspected.child<QScrollArea>("fieldsScrollArea");
        scrollArea->ensureWidgetVisible(inspected.child<QWidget>("massPropertiesGroup"));
        QTRY_VERIFY(!mass->text().isEmpty());
        QVERIFY(mass->isReadOnly());
        QVERIFY(std::abs(shownNumber(mass) - fromMesh.mass) <= 1e-6 * fromMesh.mass);

        // Ticking "Type values" starts from the mesh's, so the motion does not change.
        const int steps = inspected.undoSteps();
        test::clickIndicator(inspected.child<QCheckBox>("massTypedCheck"));
        QCOMPARE(inspected.undoSteps(), steps + 1);
        QVERIFY(document.object(inspected.object())->massOverride == fromMesh);
        QVERIFY(!mass->isReadOnly());

        // A new mass alone keeps the shape: the inertia scales with it.
        enter(mass, QStringLiteral("2.5"));
        QCOMPARE(document.object(inspected.object())->massOverride->mass, 2.5);
        QCOMPARE(inspected.undoSteps(), steps + 2);
        const Eigen::Matrix3d scaled = fromMesh.inertia * (2.5 / fromMesh.mass);
        QVERIFY((document.object(inspected.object())->massOverride->inertia - scaled).norm() <= 1e-12 * scaled.norm());

        // Moments 1, 1, 3: the two smaller add up to less than the largest.
        const std::pair<const char*, const char*> moments[] = {
            {"inertiaEdit0", "1"}, {"inertiaEdit1", "1"}, {"inertiaEdit3", "0"}, {"inertiaEdit4", "0"}, {"inertiaEdit5", "0"}};
        for (const auto& [name, text] : moments)
            typeOver(inspected.field(name), QString::fromLatin1(text));
        enter(inspected.field("inertiaEdit2"), QStringLiteral("3"));
        QCOMPARE(inspected.undoSteps(), steps + 2);
        QVERIFY(!inspected.child<QLabel>("massMessageLabel")->isHidden());
        QVERIFY2(inspected.child<QLabel>("massMessageLabel")->text().contains(QStringLiteral("no body has this inertia")),
                 qPrintable(inspected.child<QLabel>("massMessageLabel")->text()));
        QVERIFY((document.object(inspected.object())->massOverride->inertia - scaled).norm() <= 1e-12 * scaled.norm());

        // Unticking goes back to the mesh's, one more step; undoing it brings the typed mass back.
        scrollArea->ensureWidgetVisible(inspected.child<QCheckBox>("massTypedCheck"));
        test::clickIndicator(inspected.child<QCheckBox>("massTypedCheck"));
        QVERIFY(!document.object(inspected.object())->massOverride);
        QVERIFY(mass->isReadOnly());
        document.undoStack().undo();
        QCOMPARE(document.object(inspected.object())->massOverride->mass, 2.5);
        QCOMPARE(shownNumber(mass), 2.5);
    }

    // The Body group shows the rounding noise of a tensor as 0 and keeps the exact value behind it; a small
    // product of inertia that is really there still shows.
    void theInertiaShowsNoRoundingNoise()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        model::Document& document = inspected.window().document();
        inspected.child<QScrollArea>("fieldsScrollArea")->ensureWidgetVisible(inspected.child<QWidget>("massPropertiesGroup"));
        QLineEdit* ixx = inspected.field("inertiaEdit0");
        QLineEdit* ixy = inspected.field("inertiaEdit3");

        // A ship-sized block, 100,000 t and 300 × 40 × 30 m, turned a quarter turn about z: R·D·Rᵀ, whose
        // Ixy is 0 in truth but (Ixx − Iyy)·sin·cos with cos ≈ 6e-17 in doubles, about 1e-17 of the largest
        // entry and yet large enough to show in six places.
        const double mass = 1e8;
        const Eigen::Vector3d moments = mass / 12.0 * Eigen::Vector3d(40.0 * 40.0 + 30.0 * 30.0, 300.0 * 300.0 + 30.0 * 30.0,
                                                                      300.0 * 300.0 + 40.0 * 40.0);
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(radians(90.0), Eigen::Vector3d::UnitZ()).toRotationMatrix();
        const Eigen::Matrix3d product = turn * moments.asDiagonal() * turn.transpose();
        const Eigen::Matrix3d turned = (product + product.transpose()) / 2.0;
        QVERIFY(std::abs(turned(0, 1)) >= 1e-6);
        QVERIFY(std::abs(turned(0, 1)) < 1e-15 * moments.maxCoeff());
        document.push(new model::SetMassOverrideCommand(document, inspected.object(), MassProperties{mass, Eigen::Vector3d::Zero(), turned}));
        QTRY_COMPARE(ixy->text(), QStringLiteral("0"));
        for (const char* name : {"inertiaEdit4", "inertiaEdit5"})
            QCOMPARE(inspected.field(name)->text(), QStringLiteral("0"));
        QVERIFY(std::abs(shownNumber(ixx) - moments[1]) <= 1e-12 * moments[1]);

        // Typing Ixx alone stores the other entries as they were, the noise too: the text is not the value.
        const double typedIxx = 7.6e11;
        enter(ixx, QStringLiteral("760000000000"));
        const Eigen::Matrix3d& stored = document.object(inspected.object())->massOverride->inertia;
        QCOMPARE(stored(0, 0), typedIxx);
        QCOMPARE(stored(0, 1), turned(0, 1));
        QCOMPARE(ixy->text(), QStringLiteral("0"));

        // A body of moments 1, 2, 2.5 kg·m² with Ixy at 1e-4 of the largest shows it.
        document.push(new model::SetMassOverrideCommand(document, inspected.object(),
                                                        MassProperties{1.0, Eigen::Vector3d::Zero(), inertiaTensor({1.0, 2.0, 2.5, 2.5e-4, 0.0, 0.0})}));
        QTRY_COMPARE(ixy->text(), QStringLiteral("0.00025"));
    }

    void theConstraintCheckBoxTogglesTheKeyAsOneUndoStep()
    {
        InspectedWindow inspected(kQuarterTurnKey);
        const int steps = inspected.undoSteps();
        QCheckBox* constrained = inspected.child<QCheckBox>("constrainedCheck");
        test::clickIndicator(constrained);
        QVERIFY(!inspected.key(kQuarterTurnKey).constrained);
        QVERIFY(!constrained->isChecked());
        QCOMPARE(inspected.undoSteps(), steps + 1);
        inspected.window().document().undoStack().undo();
        QVERIFY(inspected.key(kQuarterTurnKey).constrained);
        QVERIFY(constrained->isChecked());
    }

    void aKeyNearGimbalLockShowsTheWarningAndOneAwayFromItDoesNot()
    {
        constexpr std::size_t kLastKey = 5;
        InspectedWindow inspected(kLastKey);
        QFrame* warning = inspected.child<QFrame>("gimbalWarningFrame");
        QVERIFY(warning->isHidden());
        // Extrinsic xyz locks where the turn about y is ±90°: x and z then turn about the same axis.
        typeOver(inspected.field("euler1Edit"), QStringLiteral("10"));
        typeOver(inspected.field("euler2Edit"), QStringLiteral("88"));
        enter(inspected.field("euler3Edit"), QStringLiteral("20"));
        QVERIFY(!warning->isHidden());
        QVERIFY(inspected.child<QLabel>("gimbalWarningLabel")->text().startsWith(QStringLiteral("Near gimbal lock")));

        inspected.window().selection().selectKey(inspected.object(), kQuarterTurnKey);
        QVERIFY(warning->isHidden());
        inspected.window().selection().selectKey(inspected.object(), kLastKey);
        QVERIFY(!warning->isHidden());

        // A turn about z alone locks zxz, whose middle angle is then 0.
        inspected.window().selection().selectKey(inspected.object(), kQuarterTurnKey);
        QTest::keyClicks(inspected.child<QComboBox>("eulerOrderCombo"), QStringLiteral("ZXZ"));
        QCOMPARE(inspected.child<QComboBox>("eulerOrderCombo")->currentText(), QStringLiteral("ZXZ"));
        QVERIFY(!warning->isHidden());
    }
};

QTEST_MAIN(TestInspector)
#include "tst_inspector.moc"
