#include "app/key_clipboard_actions.h"

#include "model/commands/replace_keyframes_command.h"
#include "model/json_field.h"
#include "model/key_clipboard.h"
#include "model/key_edits.h"

#include <QAction>
#include <QClipboard>
#include <QGuiApplication>
#include <QMimeData>
#include <QStatusBar>

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

namespace gyre::app {

namespace {

constexpr int kMessageMilliseconds = 5000;

} // namespace

KeyClipboardActions::KeyClipboardActions(model::Document& document, Selection& selection, QAction* copy,
                                         QAction* paste, QStatusBar* statusBar, QObject* parent)
    : QObject(parent)
    , document_(document)
    , selection_(selection)
    , copy_(copy)
    , paste_(paste)
    , statusBar_(statusBar)
{
    connect(copy_, &QAction::triggered, this, &KeyClipboardActions::copy);
    connect(paste_, &QAction::triggered, this, &KeyClipboardActions::paste);
    connect(&selection_, &Selection::changed, this, &KeyClipboardActions::updateActions);
    updateActions();
}

void KeyClipboardActions::copy()
{
    model::KeyClipboard clipboard;
    const double time = document_.scene().currentTime;
    if (selection_.keys().empty()) {
        const model::SceneObject* object = selection_.selectedObject();
        if (object == nullptr)
            return;
        clipboard.pose = true;
        try {
            clipboard.objects.push_back({object->name, {{0.0, document_.motion(object->id)->motion().at(time), true}}});
        } catch (const std::invalid_argument& error) {
            // A motion that cannot be built (a free flight with no solution) has no pose to copy.
            statusBar_->showMessage(tr("Cannot copy the pose: %1").arg(QString::fromUtf8(error.what())),
                                    kMessageMilliseconds);
            return;
        }
    } else {
        double first = std::numeric_limits<double>::infinity();
        for (const auto& [id, key] : selection_.keys())
            first = std::min(first, document_.object(id)->track.keys[key].time);
        for (model::ObjectId id : selection_.objects()) {
            const model::SceneObject& object = *document_.object(id);
            model::CopiedKeys copied{object.name, {}};
            for (std::size_t index : selection_.keysOf(id)) {
                model::Keyframe key = object.track.keys[index];
                key.time -= first;
                copied.keys.push_back(key);
            }
            if (!copied.keys.empty())
                clipboard.objects.push_back(std::move(copied));
        }
    }
    const QByteArray json = model::keyClipboardJson(clipboard);
    auto* data = new QMimeData;
    data->setData(QString::fromLatin1(model::kKeyClipboardMimeType), json);
    data->setText(QString::fromUtf8(json));
    QGuiApplication::clipboard()->setMimeData(data);
}

void KeyClipboardActions::paste()
{
    const QMimeData* data = QGuiApplication::clipboard()->mimeData();
    if (data == nullptr)
        return;
    const QString mimeType = QString::fromLatin1(model::kKeyClipboardMimeType);
    const QByteArray text = data->hasFormat(mimeType) ? data->data(mimeType) : data->text().toUtf8();
    model::KeyClipboard clipboard;
    try {
        clipboard = model::parseKeyClipboard(text);
    } catch (const model::FieldError& error) {
        tell(tr("Cannot paste: %1").arg(QString::fromUtf8(error.what())));
        return;
    }
    const double time = document_.scene().currentTime;
    // Each copied object's keys, and the selected object they go to.
    std::vector<std::pair<model::ObjectId, const model::CopiedKeys*>> targets;
    if (clipboard.pose) {
        for (model::ObjectId id : selection_.objects())
            targets.emplace_back(id, &clipboard.objects.front());
    } else if (clipboard.objects.size() == 1) {
        if (selection_.object() != model::kNoObject)
            targets.emplace_back(selection_.object(), &clipboard.objects.front());
    } else {
        for (const model::CopiedKeys& copied : clipboard.objects)
            for (model::ObjectId id : selection_.objects())
                if (document_.object(id)->name == copied.name) {
                    targets.emplace_back(id, &copied);
                    break;
                }
    }
    if (targets.empty()) {
        tell(clipboard.objects.size() > 1 ? tr("Cannot paste: no selected object has the name of a copied one")
                                          : tr("Cannot paste: no object is selected"));
        return;
    }
    model::ObjectKeys keys;
    std::set<KeyRef> pasted;
    const auto byTime = [](const model::Keyframe& a, const model::Keyframe& b) { return a.time < b.time; };
    for (const auto& [id, copied] : targets) {
        std::vector<model::Keyframe> added = copied->keys;
        for (model::Keyframe& key : added)
            key.time += time;
        std::vector<model::Keyframe> merged = model::withKeys(document_.object(id)->track.keys, added);
        for (std::size_t index = 0; index < merged.size(); ++index)
            if (std::binary_search(added.begin(), added.end(), merged[index], byTime))
                pasted.insert({id, index});
        keys.emplace_back(id, std::move(merged));
    }
    try {
        document_.push(new model::ReplaceKeyframesCommand(document_, std::move(keys), model::ReplaceKeyframesCommand::Edit::Paste));
    } catch (const std::invalid_argument& error) {
        tell(tr("Cannot paste: %1").arg(QString::fromUtf8(error.what())));
        return;
    }
    selection_.selectKeys(pasted, false);
}

void KeyClipboardActions::updateActions()
{
    copy_->setEnabled(selection_.selectedObject() != nullptr);
    paste_->setEnabled(selection_.selectedObject() != nullptr);
}

void KeyClipboardActions::tell(const QString& message)
{
    statusBar_->showMessage(message, kMessageMilliseconds);
}

} // namespace gyre::app
