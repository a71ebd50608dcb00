#include "app/euler_convention_choosers.h"

#include <QComboBox>
#include <QCoreApplication>

namespace gyre::app {

namespace {

// One way of a link: `to` follows `from`. setCurrentIndex emits nothing when the index is already
// the one asked for, so the two ways do not chase each other.
void follow(QComboBox& from, QComboBox& to)
{
    QObject::connect(&from, &QComboBox::currentIndexChanged, &to, &QComboBox::setCurrentIndex);
}

} // namespace

void fillConventionChoosers(QComboBox& order, QComboBox& frame)
{
    for (const bool properEuler : {false, true}) {
        for (const EulerConvention& convention : EulerConvention::all()) {
            if (convention.frame == AngleFrame::Extrinsic && convention.isProperEuler() == properEuler) {
                const QString name = QString::fromStdString(convention.order());
                order.addItem(name.toUpper(), name);
            }
        }
    }
    frame.addItem(QCoreApplication::translate("gyre::app::InspectorWidget", "extrinsic (fixed axes)"),
                  static_cast<int>(AngleFrame::Extrinsic));
    frame.addItem(QCoreApplication::translate("gyre::app::InspectorWidget", "intrinsic (moving axes)"),
                  static_cast<int>(AngleFrame::Intrinsic));
}

EulerConvention chosenConvention(const QComboBox& order, const QComboBox& frame)
{
    const auto angleFrame = static_cast<AngleFrame>(frame.currentData().toInt());
    // The orders in the chooser are those EulerConvention::all() names, so they parse.
    return *EulerConvention::parse(order.currentData().toString().toStdString(), angleFrame);
}

void showConvention(QComboBox& order, QComboBox& frame, const EulerConvention& convention)
{
    order.setCurrentIndex(order.findData(QString::fromStdString(convention.order())));
    frame.setCurrentIndex(frame.findData(static_cast<int>(convention.frame)));
}

void linkConventionChoosers(QComboBox& order, QComboBox& frame, QComboBox& otherOrder, QComboBox& otherFrame)
{
    otherOrder.setCurrentIndex(order.currentIndex());
    otherFrame.setCurrentIndex(frame.currentIndex());
    follow(order, otherOrder);
    follow(otherOrder, order);
    follow(frame, otherFrame);
    follow(otherFrame, frame);
}

} // namespace gyre::app
