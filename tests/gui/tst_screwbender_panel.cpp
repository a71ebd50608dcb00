// The ScrewBender panel driven as the artist drives it: choosing from its combo boxes, typing a level,
// clicking the sequence and decoupled buttons. Each change must reach the selected track as one undo
// step of its own.

#include "inspected_window.h"

#include "gui_test_support.h"
#include "model/commands/set_fit_parameter_command.h"
#include "model/commands/set_subdivision_command.h"
#include "model/value_checks.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>
#include <QTest>

#include <iterator>

using namespace gyre;
using test::InspectedWindow;

class TestScrewBenderPanel : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { test::useTestSettings(); }

    void showsTheSampleTrack()
    {
        InspectedWindow inspected(0);
        // The sample is a cycle of 6 poses subdivided by Jarek's scheme 4 times: 6·2⁴ poses.
        QCOMPARE(inspected.child<QComboBox>("interpolationCombo")->currentText(), QStringLiteral("Screw motion (ScrewBender)"));
        QCOMPARE(inspected.child<QComboBox>("schemeCombo")->currentText(), QStringLiteral("Jarek"));
        QCOMPARE(inspected.child<QSpinBox>("levelsSpin")->value(), 4);
        QVERIFY(inspected.child<QRadioButton>("cyclicRadio")->isChecked());
        QVERIFY(!inspected.child<QCheckBox>("decoupledCheck")->isChecked());
        QCOMPARE(inspected.child<QLabel>("poseCountLabel")->text(), QStringLiteral("96 from 6 keyframes"));
    }

    void everyInterpolationMethodCanBeChosenAsOneUndoStep()
    {
        InspectedWindow inspected(0);
        QComboBox* methods = inspected.child<QComboBox>("interpolationCombo");
        const InterpolationMethod expected[] = {InterpolationMethod::Slerp,      InterpolationMethod::Nlerp,
                                                InterpolationMethod::Squad,      InterpolationMethod::Hermite,
                                                InterpolationMethod::Euler,      InterpolationMethod::EulerCubic,
                                                InterpolationMethod::Screw,      InterpolationMethod::Ballistic};
        QCOMPARE(methods->count(), int(std::size(expected)));
        for (int index = 0; index < methods->count(); ++index) {
            const int steps = inspected.undoSteps();
            test::choose(methods, index);
            QCOMPARE(inspected.window().selection().selectedObject()->track.interpolation, expected[index]);
            QCOMPARE(inspected.undoSteps(), steps + 1);
        }
        inspected.window().document().undoStack().undo();
        QCOMPARE(inspected.window().selection().selectedObject()->track.interpolation, InterpolationMethod::Screw);
        QCOMPARE(methods->currentIndex(), 6);
    }

    void eachSubdivisionSettingIsOneUndoStep()
    {
        InspectedWindow inspected(0);
        QUndoStack& stack = inspected.window().document().undoStack();
        const auto subdivision = [&inspected] { return inspected.window().selection().selectedObject()->track.subdivision; };
        const int steps = inspected.undoSteps();

        test::choose(inspected.child<QComboBox>("schemeCombo"), 1);
        QCOMPARE(subdivision().scheme, SubdivisionScheme::FourPointB);
        QCOMPARE(inspected.undoSteps(), steps + 1);

        QSpinBox* levels = inspected.child<QSpinBox>("levelsSpin");
        QCOMPARE(levels->maximum(), model::kMaxSubdivisionLevels);
        levels->setFocus(Qt::TabFocusReason);
        QTest::keyClick(levels, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(levels, QStringLiteral("6"));
        QTest::keyClick(levels, Qt::Key_Return);
        QCOMPARE(subdivision().levels, 6);
        QCOMPARE(inspected.undoSteps(), steps + 2);
        QCOMPARE(inspected.child<QLabel>("poseCountLabel")->text(), QStringLiteral("384 from 6 keyframes"));

        test::clickIndicator(inspected.child<QRadioButton>("openRadio"));
        QVERIFY(!subdivision().cyclic);
        QCOMPARE(inspected.undoSteps(), steps + 3);
        // Open: (6 − 1)·2⁶ + 1 poses.
        QCOMPARE(inspected.child<QLabel>("poseCountLabel")->text(), QStringLiteral("321 from 6 keyframes"));

        test::clickIndicator(inspected.child<QCheckBox>("decoupledCheck"));
        QVERIFY(subdivision().decoupled);
        QCOMPARE(inspected.undoSteps(), steps + 4);

        stack.undo();
        QVERIFY(!subdivision().decoupled);
        QVERIFY(!inspected.child<QCheckBox>("decoupledCheck")->isChecked());
        stack.undo();
        QVERIFY(subdivision().cyclic);
        QVERIFY(inspected.child<QRadioButton>("cyclicRadio")->isChecked());
        stack.undo();
        QCOMPARE(subdivision().levels, 4);
        QCOMPARE(levels->value(), 4);
        stack.undo();
        QCOMPARE(subdivision().scheme, SubdivisionScheme::Jarek);
        QCOMPARE(inspected.child<QComboBox>("schemeCombo")->currentText(), QStringLiteral("Jarek"));
    }

    void withoutASelectedObjectThePanelSaysSoAndIsDisabled()
    {
        InspectedWindow inspected(0);
        inspected.window().selection().clear();
        QVERIFY(!inspected.child<QLabel>("noObjectLabel")->isHidden());
        QVERIFY(!inspected.child<QComboBox>("interpolationCombo")->isEnabled());
        QVERIFY(!inspected.child<QSpinBox>("levelsSpin")->isEnabled());
    }

    // A form off screen does nothing when the track changes, and shows the change once it is back:
    // closed (the ScrewBender panel), or tabbed behind another dock (the fit panel behind the inspector).
    void aFormOffScreenCatchesUpWhenShown()
    {
        InspectedWindow inspected(0);
        model::Document& document = inspected.window().document();
        QLabel* poseCount = inspected.child<QLabel>("poseCountLabel");
        auto* screwBenderDock = inspected.child<QDockWidget>("screwBenderDock");
        screwBenderDock->hide();
        SubdivisionSettings settings = inspected.window().selection().selectedObject()->track.subdivision;
        settings.levels = 6;
        document.push(new model::SetSubdivisionCommand(document, inspected.object(), settings));
        QCoreApplication::processEvents();
        QCOMPARE(poseCount->text(), QStringLiteral("96 from 6 keyframes"));
        screwBenderDock->show();
        QTRY_COMPARE(poseCount->text(), QStringLiteral("384 from 6 keyframes"));

        // The fit's form is the exception: it follows at once, behind the inspector too, so that its
        // Fit button is right the moment it is raised.
        auto* alpha = inspected.child<QDoubleSpinBox>("alphaSpin");
        QVERIFY(inspected.child<QDockWidget>("fitDock")->visibleRegion().isEmpty()); // behind the inspector
        QVERIFY(alpha->value() != 0.5);
        document.push(new model::SetFitParameterCommand(document, inspected.object(), model::FitParameter::Alpha, 0.5));
        QCOMPARE(alpha->value(), 0.5);
    }
};

QTEST_MAIN(TestScrewBenderPanel)
#include "tst_screwbender_panel.moc"
