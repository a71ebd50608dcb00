// The edits of selected keys below the window: ReplaceKeyframesCommand (several objects, one undo
// step; refusals; merged within a gesture, and no step when a gesture comes back to where it began),
// the key lists it is given (key_edits.h), and the clipboard's JSON (key_clipboard.h), which reads
// back exactly what was written and refuses, whole, anything else.

#include "model/commands/import_objects_command.h"
#include "model/commands/replace_keyframes_command.h"
#include "model/gesture.h"
#include "model/json_field.h"
#include "model/key_clipboard.h"
#include "model/key_edits.h"

#include <QTest>

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

using namespace gyre;
using namespace gyre::model;

namespace {

std::vector<Keyframe> keysAt(std::initializer_list<double> times)
{
    std::vector<Keyframe> keys;
    for (double time : times)
        keys.push_back({time, {Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * time, Eigen::Vector3d::UnitY())), {0, time, 0}}, true});
    return keys;
}

std::vector<double> timesOf(const std::vector<Keyframe>& keys)
{
    std::vector<double> times;
    for (const Keyframe& key : keys)
        times.push_back(key.time);
    return times;
}

// Two objects, "a" keyed at 0, 1, 2 s and "b" at 0, 3 s; their document ids.
std::pair<ObjectId, ObjectId> twoObjects(Document& document)
{
    SceneObject a;
    a.id = 1;
    a.name = QStringLiteral("a");
    a.track.keys = keysAt({0, 1, 2});
    SceneObject b;
    b.id = 2;
    b.name = QStringLiteral("b");
    b.track.keys = keysAt({0, 3});
    auto* import = new ImportObjectsCommand(document, {a, b});
    const std::vector<ObjectId> ids = import->ids();
    document.undoStack().push(import);
    return {ids[0], ids[1]};
}

bool refused(const std::function<void()>& make)
{
    try {
        make();
    } catch (const std::invalid_argument&) {
        return true;
    }
    return false;
}

} // namespace

class TstKeyEdits : public QObject {
    Q_OBJECT

private slots:
    void replacesTheKeysOfSeveralObjectsInOneStep()
    {
        Document document;
        const auto [a, b] = twoObjects(document);
        const int steps = document.undoStack().count();
        document.push(new ReplaceKeyframesCommand(document, {{a, keysAt({5})}, {b, keysAt({1, 2, 4})}},
                                                  ReplaceKeyframesCommand::Edit::Paste));
        QCOMPARE(document.undoStack().count(), steps + 1);
        QCOMPARE(document.undoStack().undoText(), QStringLiteral("Paste Keyframes"));
        QCOMPARE(timesOf(document.object(a)->track.keys), (std::vector<double>{5}));
        QCOMPARE(timesOf(document.object(b)->track.keys), (std::vector<double>{1, 2, 4}));
        document.undoStack().undo();
        QCOMPARE(timesOf(document.object(a)->track.keys), (std::vector<double>{0, 1, 2}));
        QCOMPARE(timesOf(document.object(b)->track.keys), (std::vector<double>{0, 3}));

        using Edit = ReplaceKeyframesCommand::Edit;
        QVERIFY(refused([&] { ReplaceKeyframesCommand(document, {{99, keysAt({1})}}, Edit::Move); }));
        QVERIFY(refused([&] { ReplaceKeyframesCommand(document, {{a, keysAt({1})}, {a, keysAt({2})}}, Edit::Move); }));
        QVERIFY(refused([&] { ReplaceKeyframesCommand(document, {{a, keysAt({2, 1})}}, Edit::Move); }));
        QVERIFY(refused([&] { ReplaceKeyframesCommand(document, {{a, keysAt({1, 1})}}, Edit::Move); }));
    }

    void aGestureIsOneStepAndNoneWhenItComesBack()
    {
        Document document;
        const auto [a, b] = twoObjects(document);
        const int steps = document.undoStack().count();
        const std::vector<Keyframe> before = document.object(a)->track.keys;
        using Edit = ReplaceKeyframesCommand::Edit;
        {
            Gesture drag(document);
            for (double shift : {0.1, 0.2, 0.3})
                drag.push(new ReplaceKeyframesCommand(document, {{a, shiftedKeys(before, {1}, shift)}}, Edit::Move));
        }
        QCOMPARE(document.undoStack().count(), steps + 1);
        QCOMPARE(timesOf(document.object(a)->track.keys), (std::vector<double>{0, 1.3, 2}));
        document.undoStack().undo();
        QCOMPARE(timesOf(document.object(a)->track.keys), (std::vector<double>{0, 1, 2}));
        {
            Gesture drag(document);
            drag.push(new ReplaceKeyframesCommand(document, {{a, shiftedKeys(before, {1}, 0.4)}}, Edit::Move));
            drag.push(new ReplaceKeyframesCommand(document, {{a, before}}, Edit::Move));
        }
        QCOMPARE(document.undoStack().index(), steps);
        QCOMPARE(document.undoStack().count(), steps);
    }

    void keyListsForTheEdits()
    {
        const std::vector<Keyframe> keys = keysAt({0, 1, 2, 3, 5});
        QCOMPARE(timesOf(withoutKeys(keys, {1, 3})), (std::vector<double>{0, 2, 5}));
        // An added key at a key's time takes its place.
        std::vector<Keyframe> added = keysAt({1, 4});
        added[0].constrained = false;
        const std::vector<Keyframe> merged = withKeys(keys, added);
        QCOMPARE(timesOf(merged), (std::vector<double>{0, 1, 2, 3, 4, 5}));
        QCOMPARE(merged[1].constrained, false);
        // Keys 1 and 2 move together: held by 0 and 3, a gap of 0.1 kept; key 4 alone by 3 and the range's end 6.
        const auto [lower, upper] = shiftRange(keys, {1, 2}, 0.1, 0.0, 10.0);
        QVERIFY(std::abs(lower - -0.9) < 1e-12);
        QVERIFY(std::abs(upper - 0.9) < 1e-12);
        const auto [lowerEnd, upperEnd] = shiftRange(keys, {1, 2, 4}, 0.1, 0.0, 6.0);
        QVERIFY(std::abs(lowerEnd - -0.9) < 1e-12);
        QVERIFY(std::abs(upperEnd - 0.9) < 1e-12);
        QCOMPARE(shiftRange(keys, {4}, 0.1, 0.0, 5.5).second, 0.5);
        QCOMPARE(timesOf(shiftedKeys(keys, {1, 2}, 0.5)), (std::vector<double>{0, 1.5, 2.5, 3, 5}));
        // Times doubled about 0: keys 1 and 2 to 2 and 4 would pass the key at 3.
        const auto twice = [](double time) { return 2.0 * time; };
        QVERIFY(!retimedKeys(keys, {1, 2}, twice, 0.0));
        QVERIFY(!retimedKeys(keys, {1}, twice, 0.0)); // onto the key at 2 s
        const auto later = [](double time) { return time + 0.5; };
        QCOMPARE(timesOf(*retimedKeys(keys, {3}, later, 0.0)), (std::vector<double>{0, 1, 2, 3.5, 5}));
    }

    void theClipboardReadsBackWhatItWrote()
    {
        KeyClipboard copied{false, {{QStringLiteral("a"), keysAt({0, 1.0 / 3.0})}, {QStringLiteral("b ü"), keysAt({0.7})}}};
        copied.objects[0].keys[1].constrained = false;
        const KeyClipboard read = parseKeyClipboard(keyClipboardJson(copied));
        QCOMPARE(read.pose, false);
        QCOMPARE(read.objects.size(), std::size_t{2});
        QCOMPARE(read.objects[1].name, QStringLiteral("b ü"));
        for (std::size_t o = 0; o < 2; ++o) {
            QCOMPARE(read.objects[o].keys.size(), copied.objects[o].keys.size());
            for (std::size_t k = 0; k < read.objects[o].keys.size(); ++k) {
                const Keyframe& x = read.objects[o].keys[k];
                const Keyframe& y = copied.objects[o].keys[k];
                QCOMPARE(x.time, y.time);
                QCOMPARE(x.pose.orientation.coeffs(), y.pose.orientation.coeffs());
                QCOMPARE(x.pose.position, y.pose.position);
                QCOMPARE(x.constrained, y.constrained);
            }
        }
    }

    void theClipboardRefusesAnythingElseWhole()
    {
        const QByteArray good = keyClipboardJson({false, {{QStringLiteral("a"), keysAt({0, 1})}}});
        QByteArray decreasing = good;
        decreasing.replace(decreasing.lastIndexOf("\"time\": 1"), 9, "\"time\": -1");
        QByteArray zero = good;
        zero.replace(zero.indexOf("\"position\""), 10, "\"positions\"");
        QByteArray twoKeyPose = good;
        twoKeyPose.replace("\"pose\": false", "\"pose\": true");
        for (const QByteArray& text : {QByteArray("hello"), QByteArray("[1, 2]"), QByteArray("{\"format\": \"gyre-project\"}"),
                                       decreasing, zero, twoKeyPose,
                                       QByteArray(kMaxKeyClipboardBytes + 1, ' ')}) {
            bool threw = false;
            try {
                parseKeyClipboard(text);
            } catch (const FieldError&) {
                threw = true;
            }
            QVERIFY2(threw, text.left(80).constData());
        }
        QCOMPARE(parseKeyClipboard(good).objects.front().keys.size(), std::size_t{2});
    }
};

QTEST_MAIN(TstKeyEdits)
#include "tst_key_edits.moc"
