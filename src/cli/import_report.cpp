#include "cli/import_report.h"

#include "core/number_text.h"

#include <algorithm>

namespace gyre::cli {

namespace {

std::string joined(const QStringList& names)
{
    return names.join(QStringLiteral(", ")).toStdString();
}

std::string takeNumbers(const std::vector<std::size_t>& takes)
{
    std::string text;
    for (const std::size_t take : takes)
        text += (text.empty() ? "" : ", ") + std::to_string(take);
    return text;
}

// " (the FBX time mode)" when the file's value was applied, else what the file said.
std::string origin(bool asTheFileSays, const QString& source, const std::string& fileValue)
{
    return asTheFileSays ? " (" + source.toStdString() + ")" : " (as asked; the file says " + fileValue + ")";
}

std::string upText(io::UpAxis up) { return up == io::UpAxis::Z ? "Z" : "Y"; }

} // namespace

std::string animationList(const io::SceneImport& imported)
{
    std::string text;
    for (std::size_t i = 0; i < imported.animations.size(); ++i) {
        const io::AnimationSummary& animation = imported.animations[i];
        const bool used = std::find(imported.takes.begin(), imported.takes.end(), i) != imported.takes.end();
        text += "  " + std::to_string(i) + ": '" + animation.name.toStdString() + "', " +
                formatNumber(animation.durationSeconds) + " s, moves " +
                (animation.nodes.isEmpty() ? std::string("nothing") : joined(animation.nodes)) +
                (used ? " (imported)\n" : "\n");
    }
    return text;
}

std::string takeChoiceLine(const io::SceneImport& imported)
{
    switch (imported.takeRule) {
    case io::TakeRule::NoAnimation:
        return "imported: no animation";
    case io::TakeRule::Single:
        return "imported: animation 0";
    case io::TakeRule::Disjoint:
        return "imported: all of them, merged, as each moves nodes no other moves";
    case io::TakeRule::BlenderActions:
        return "imported: " + takeNumbers(imported.takes) +
               ", Blender's takes \"Object|Action\", each object playing its own action";
    case io::TakeRule::ChoiceNeeded:
        return "imported: a choice is needed (gyre-cli import --animation), as they move the same nodes";
    case io::TakeRule::Chosen:
        return "imported: " + takeNumbers(imported.takes);
    }
    return {};
}

std::string settingsLine(const io::SceneImport& imported)
{
    const io::ImportSettings& applied = imported.applied;
    const io::FileSettings& file = imported.file;
    std::string line = formatNumber(applied.fps) + " fps" +
                       origin(applied.fps == file.values.fps, file.fpsSource, formatNumber(file.values.fps) + " fps");
    line += ", 1 unit = " + formatNumber(applied.metresPerUnit) + " m" +
            origin(applied.metresPerUnit == file.values.metresPerUnit, file.unitSource,
                   formatNumber(file.values.metresPerUnit) + " m");
    line += ", " + upText(applied.up) + "-up" + (applied.up == io::UpAxis::Y ? " turned Z-up" : "") +
            origin(applied.up == file.values.up, file.upSource, upText(file.values.up) + "-up");
    if (imported.timeShift != 0.0)
        line += ", key times moved by " + formatNumber(imported.timeShift) + " s to start at 0";
    return line;
}

} // namespace gyre::cli
