#include "app/number_fields.h"

#include "core/number_text.h"

#include <QApplication>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace gyre::app {

namespace {

// Beyond this magnitude fixed notation would spell out hundreds of digits.
constexpr double kLargestFixedNotation = 1e15;

} // namespace

NumberFields::NumberFields(std::vector<QLineEdit*> fields, QStringList names, int decimals, QObject* parent)
    : QObject(parent)
    , fields_(std::move(fields))
    , names_(std::move(names))
    , decimals_(decimals)
    , shown_(fields_.size(), 0.0)
{
    Q_ASSERT(static_cast<std::size_t>(names_.size()) == fields_.size());
    for (QLineEdit* field : fields_)
        connect(field, &QLineEdit::returnPressed, this, &NumberFields::finishIfEdited);
    connect(qApp, &QApplication::focusChanged, this, [this](QWidget* previous, QWidget* current) {
        const auto isOurs = [this](QWidget* widget) {
            return std::find(fields_.begin(), fields_.end(), widget) != fields_.end();
        };
        // No widget at all has the focus while the window is inactive or being closed: the artist
        // has not moved on, and the focus comes back to the field.
        if (isOurs(previous) && current != nullptr && !isOurs(current))
            finishIfEdited();
    });
}

void NumberFields::show(const std::vector<double>& values, double zeroBelow)
{
    Q_ASSERT(values.size() == fields_.size());
    shown_ = values;
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        fields_[i]->setText(roundedNumberText(values[i], decimals_, zeroBelow));
        fields_[i]->setToolTip(tr("Exact value: %1").arg(QString::fromStdString(formatNumber(values[i]))));
        fields_[i]->setCursorPosition(0);
    }
}

void NumberFields::clear()
{
    // setText, unlike QLineEdit::clear, leaves the field unmodified.
    for (QLineEdit* field : fields_) {
        field->setText(QString());
        field->setToolTip(QString());
    }
}

bool NumberFields::isEdited() const
{
    return std::any_of(fields_.begin(), fields_.end(), [](const QLineEdit* field) { return field->isModified(); });
}

std::vector<double> NumberFields::values() const
{
    std::vector<double> values = shown_;
    for (std::size_t i = 0; i < fields_.size(); ++i) {
        if (!fields_[i]->isModified())
            continue;
        try {
            values[i] = parseFiniteNumber(fields_[i]->text().toStdString());
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument(names_[static_cast<qsizetype>(i)].toStdString() + ": " + error.what());
        }
    }
    return values;
}

void NumberFields::finishIfEdited()
{
    if (isEdited())
        emit editingFinished();
}

QString roundedNumberText(double value, int decimals, double zeroBelow)
{
    if (std::abs(value) < zeroBelow)
        return QStringLiteral("0");
    if (!(std::abs(value) < kLargestFixedNotation))
        return QString::fromStdString(formatNumber(value));
    QString text = QString::number(value, 'f', decimals);
    if (text.contains(QLatin1Char('.'))) {
        while (text.endsWith(QLatin1Char('0')))
            text.chop(1);
        if (text.endsWith(QLatin1Char('.')))
            text.chop(1);
    }
    // A small negative number rounds to "-0", which reads as a different value from 0.
    if (text == QLatin1String("-0"))
        text = QStringLiteral("0");
    return text;
}

} // namespace gyre::app
