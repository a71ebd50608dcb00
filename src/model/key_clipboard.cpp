#include "model/key_clipboard.h"

#include "model/input_error.h"
#include "model/json_field.h"
#include "model/project_blocks.h"
#include "model/project_file.h"
#include "model/value_checks.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>

namespace gyre::model {

namespace {

constexpr int kKeyClipboardVersion = 1;

} // namespace

QByteArray keyClipboardJson(const KeyClipboard& clipboard)
{
    QJsonArray objects;
    for (const CopiedKeys& copied : clipboard.objects) {
        QJsonArray keys;
        for (const Keyframe& key : copied.keys)
            keys.append(keyframeJson(key));
        objects.append(QJsonObject{{"name", copied.name}, {"keyframes", keys}});
    }
    const QJsonObject root{{"format", QString::fromLatin1(kKeyClipboardFormat)},
                           {"version", kKeyClipboardVersion},
                           {"pose", clipboard.pose},
                           {"objects", objects}};
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

KeyClipboard parseKeyClipboard(const QByteArray& text)
{
    const QString notKeys = FileError::tr("the text is not keys copied from Gyre");
    if (text.size() > kMaxKeyClipboardBytes)
        throw FieldError(FileError::tr("%1 bytes of text are more than the %2 that keys may take")
                             .arg(text.size())
                             .arg(kMaxKeyClipboardBytes)
                             .toStdString());
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError || !document.isObject())
        throw FieldError(notKeys.toStdString());
    const JsonField root(document.object(), QString());
    if (!root.has("format") || root.member("format").string() != QLatin1String(kKeyClipboardFormat))
        throw FieldError(notKeys.toStdString());
    root.member("version").integer(kKeyClipboardVersion, kKeyClipboardVersion);
    KeyClipboard clipboard;
    clipboard.pose = root.member("pose").boolean();
    std::size_t keyCount = 0;
    for (const JsonField& object : root.member("objects").elements()) {
        CopiedKeys copied;
        copied.name = object.member("name").string();
        const JsonField keys = object.member("keyframes");
        for (const JsonField& key : keys.elements())
            copied.keys.push_back(keyframeFromJson(key));
        keys.checked([&] { checkKeyframes(copied.keys); });
        keyCount += copied.keys.size();
        clipboard.objects.push_back(std::move(copied));
    }
    const JsonField objects = root.member("objects");
    if (keyCount == 0)
        objects.fail(FileError::tr("no keys were copied"));
    if (keyCount > kMaxProjectKeys)
        objects.fail(FileError::tr("%1 keys are more than the %2 a project may hold").arg(keyCount).arg(kMaxProjectKeys));
    if (clipboard.pose && (clipboard.objects.size() != 1 || clipboard.objects.front().keys.size() != 1))
        objects.fail(FileError::tr("a pose is one object's one key"));
    return clipboard;
}

} // namespace gyre::model
