// The undo stack as users lean on it: seeded random sequences of every kind of command, each undone
// and redone at once, must leave the document exactly as it was at every step. "Exactly" is the
// serialised project, byte for byte. Parents always come before their children. A command that
// refuses its edit must change nothing. At the end the whole stack unwinds to the initial document and
// winds forward to the final one.
//
// The commands go through the document's gestures as the views push them: an edit that repeats the
// one before continues its gesture (drags merge); other edits begin a gesture, continue the open one
// with a command of another kind (a stroke added and then edited), or are pushed alone. A step that
// a gesture brings back to where it began leaves the stack, and the document must be that earlier
// state exactly. The gestures draw from a generator of their own, so each seed's edits are those it
// always made.
//
// Four seeds of kDefaultSteps steps each by default, each seed a test function of its own that stays
// well under a minute in the sanitizer build on two busy cores. GYRE_PROPERTY_SEED runs one other
// seed, GYRE_PROPERTY_STEPS another length: a failure found that way is kept by adding its seed here.

#include "model_test_support.h"

#include "model/gesture.h"
#include "model/project_file.h"

#include <QTest>

#include <algorithm>
#include <array>
#include <optional>
#include <random>
#include <stdexcept>

using namespace gyre::model;
using namespace gyre::model::test;

namespace {

// The scene's invariant: every parent exists and comes before its children.
bool parentsComeFirst(const Scene& scene)
{
    std::vector<ObjectId> seen;
    for (const SceneObject& object : scene.objects) {
        if (object.parent != kNoObject && std::find(seen.begin(), seen.end(), object.parent) == seen.end())
            return false;
        seen.push_back(object.id);
    }
    return true;
}

constexpr int kDefaultSteps = 1000;

// A positive whole number from the environment variable `name`, or `fallback` if it is unset.
unsigned environmentNumber(const char* name, unsigned fallback)
{
    bool valid = false;
    const unsigned value = qEnvironmentVariable(name).toUInt(&valid);
    if (!qEnvironmentVariableIsSet(name))
        return fallback;
    if (!valid || value == 0)
        qFatal("%s must be a positive whole number", name);
    return value;
}

} // namespace

class TstUndoProperty : public QObject {
    Q_OBJECT

private slots:
    void randomSequences_data();
    void randomSequences();
};

void TstUndoProperty::randomSequences_data()
{
    QTest::addColumn<unsigned>("seed");
    if (qEnvironmentVariableIsSet("GYRE_PROPERTY_SEED")) {
        const unsigned seed = environmentNumber("GYRE_PROPERTY_SEED", 1);
        QTest::addRow("seed %u", seed) << seed;
        return;
    }
    for (unsigned seed : {1u, 2u, 3u, 4u})
        QTest::addRow("seed %u", seed) << seed;
}

void TstUndoProperty::randomSequences()
{
    QFETCH(unsigned, seed);
    const int steps = static_cast<int>(environmentNumber("GYRE_PROPERTY_STEPS", kDefaultSteps));
    Document document;
    QUndoStack& stack = document.undoStack();
    RandomEdits edits(seed);
    // states[i]: the serialised document after the first i commands on the stack.
    std::vector<QByteArray> states{projectBytes(document.scene())};
    std::array<int, kEditKinds> pushed{};
    int merges = 0;
    int refusals = 0;
    std::mt19937 gestureDice(seed);
    std::optional<Gesture> gesture;
    EditKind gestureKind = EditKind::ImportObjects; // of the gesture's latest command
    int pushedAlone = 0;
    int otherKindInGesture = 0;

    for (int step = 0; step < steps; ++step) {
        const EditKind kind = edits.kind(document);
        std::unique_ptr<QUndoCommand> command;
        try {
            command = edits.command(document, kind);
        } catch (const std::invalid_argument&) {
            ++refusals;
            QCOMPARE(projectBytes(document.scene()), states.back());
            continue;
        }
        if (!command)
            continue;
        // 0: alone, 1: a new gesture, 2: the open gesture, whatever kind it had.
        const unsigned choice = edits.repeating() ? 2 : std::uniform_int_distribution<unsigned>(0, 2)(gestureDice);
        if (choice != 2 || !gesture) {
            gesture.reset();
            if (choice != 0)
                gesture.emplace(document);
        }
        QCOMPARE(document.isGestureOpen(), gesture.has_value());
        const bool joinsStep = gesture && document.newestStepGesture() == gesture->id();
        if (!gesture)
            ++pushedAlone;
        else if (joinsStep && kind != gestureKind)
            ++otherKindInGesture;
        gestureKind = kind;
        const int countBefore = stack.count();
        document.push(command.release(), gesture ? gesture->id() : kNoGesture);
        ++pushed[static_cast<std::size_t>(kind)];
        if (stack.count() == countBefore) {
            // The top step now holds this edit too, its "before" state unchanged; or the edit began a
            // gesture and changed nothing.
            if (joinsStep)
                ++merges;
            states.back() = projectBytes(document.scene());
        } else if (stack.count() == countBefore + 1) {
            states.push_back(projectBytes(document.scene()));
        } else {
            // The gesture came back to where its step began, and the step went.
            QCOMPARE(stack.count(), countBefore - 1);
            states.pop_back();
            QCOMPARE(projectBytes(document.scene()), states.back());
        }
        QVERIFY(parentsComeFirst(document.scene()));
        QCOMPARE(states.size(), static_cast<std::size_t>(stack.count()) + 1);
        if (stack.count() == 0)
            continue;

        stack.undo();
        QCOMPARE(projectBytes(document.scene()), states[states.size() - 2]);
        stack.redo();
        QCOMPARE(projectBytes(document.scene()), states.back());
    }

    for (int kind = 0; kind < kEditKinds; ++kind)
        QVERIFY2(pushed[static_cast<std::size_t>(kind)] > 0, qPrintable(QStringLiteral("kind %1 never pushed").arg(kind)));
    QVERIFY(merges > 0);
    QVERIFY(refusals > 0);
    QVERIFY(pushedAlone > 0);
    QVERIFY(otherKindInGesture > 0);
    gesture.reset();
    QVERIFY(!document.isGestureOpen());

    stack.setIndex(0);
    QCOMPARE(projectBytes(document.scene()), states.front());
    QVERIFY(document.scene().objects.empty());
    stack.setIndex(stack.count());
    QCOMPARE(projectBytes(document.scene()), states.back());
}

QTEST_GUILESS_MAIN(TstUndoProperty)
#include "tst_undo_property.moc"
