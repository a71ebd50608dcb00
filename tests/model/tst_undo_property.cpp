// The undo stack as users lean on it: seeded random sequences of every kind of command, each undone
// and redone at once, must leave the document exactly as it was at every step. "Exactly" is the
// serialised project, byte for byte. Parents always come before their children. A command that
// refuses its edit must change nothing. At the end the whole stack unwinds to the initial document and
// winds forward to the final one.
//
// Four seeds of kDefaultSteps steps each by default, each seed a test function of its own that stays
// well under a minute in the sanitizer build on two busy cores. GYRE_PROPERTY_SEED runs one other
// seed, GYRE_PROPERTY_STEPS another length: a failure found that way is kept by adding its seed here.

#include "model_test_support.h"

#include "model/project_file.h"

#include <QTest>

#include <algorithm>
#include <array>
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
    std::vector<QByteArray> states{projectJson(document.scene())};
    std::array<int, kEditKinds> pushed{};
    int merges = 0;
    int refusals = 0;

    for (int step = 0; step < steps; ++step) {
        const EditKind kind = edits.kind(document);
        std::unique_ptr<QUndoCommand> command;
        try {
            command = edits.command(document, kind);
        } catch (const std::invalid_argument&) {
            ++refusals;
            QCOMPARE(projectJson(document.scene()), states.back());
            continue;
        }
        if (!command)
            continue;
        const int countBefore = stack.count();
        stack.push(command.release());
        ++pushed[static_cast<std::size_t>(kind)];
        if (stack.count() == countBefore)
            ++merges; // the top command now holds this edit too; its "before" state is unchanged
        else
            states.emplace_back();
        states.back() = projectJson(document.scene());
        QVERIFY(parentsComeFirst(document.scene()));
        QCOMPARE(states.size(), static_cast<std::size_t>(stack.count()) + 1);

        stack.undo();
        QCOMPARE(projectJson(document.scene()), states[states.size() - 2]);
        stack.redo();
        QCOMPARE(projectJson(document.scene()), states.back());
    }

    for (int kind = 0; kind < kEditKinds; ++kind)
        QVERIFY2(pushed[static_cast<std::size_t>(kind)] > 0, qPrintable(QStringLiteral("kind %1 never pushed").arg(kind)));
    QVERIFY(merges > 0);
    QVERIFY(refusals > 0);

    stack.setIndex(0);
    QCOMPARE(projectJson(document.scene()), states.front());
    QVERIFY(document.scene().objects.empty());
    stack.setIndex(stack.count());
    QCOMPARE(projectJson(document.scene()), states.back());
}

QTEST_GUILESS_MAIN(TstUndoProperty)
#include "tst_undo_property.moc"
