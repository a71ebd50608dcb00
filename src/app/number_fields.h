#pragma once
// A few line edits that hold one value together, such as the four components of a quaternion. They
// show their numbers rounded but keep the exact values behind the text, so that a field the artist
// did not touch gives back its exact value: editing one angle never rounds the other two. The fields
// are applied together, when Enter is pressed in one of them or when the focus moves on to another
// widget, so that typing a whole quaternion component by component is one edit and not four.

#include <QLineEdit>
#include <QObject>
#include <QString>
#include <QStringList>

#include <vector>

namespace gyre::app {

class NumberFields : public QObject {
    Q_OBJECT

public:
    // `names` name the fields in messages, one per field; `decimals` is how many places they show.
    NumberFields(std::vector<QLineEdit*> fields, QStringList names, int decimals, QObject* parent);

    const std::vector<QLineEdit*>& fields() const { return fields_; }

    // Shows `values`, one per field, rounded, with the exact value in each field's tool tip; the
    // fields are then unedited. A value smaller in magnitude than `zeroBelow` reads as 0 (the rounding
    // noise of a computed value), yet the field still gives back its exact value.
    void show(const std::vector<double>& values, double zeroBelow = 0.0);
    // Empties the fields: there is nothing to show.
    void clear();

    // Whether the artist has changed the text of any field since the last show().
    bool isEdited() const;
    // The exact value shown in each unedited field and the number typed into each edited one.
    // Throws std::invalid_argument, naming the field, if a typed text is not a finite number.
    std::vector<double> values() const;

signals:
    // The artist has finished an edit: pressed Enter in a field, or moved the focus to another
    // widget, after changing at least one of the fields.
    void editingFinished();

private:
    void finishIfEdited();

    std::vector<QLineEdit*> fields_;
    QStringList names_;
    int decimals_;
    std::vector<double> shown_;
};

// `value` with at most `decimals` places and no trailing zeros, as "90", "0.707107" or "-1.5"; never
// "-0", and "0" when |value| < zeroBelow. Values too large for fixed notation are written in full.
QString roundedNumberText(double value, int decimals, double zeroBelow = 0.0);

} // namespace gyre::app
