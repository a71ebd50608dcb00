#pragma once
// The graph editor's list of channels (model/motion_channels.h), one row each with a check box that
// shows or hides its curve. Names follow the Euler convention, so that the angle rows say which axis
// they turn about. No widgets: the list view shows it, and tests drive it through setData.

#include "core/euler_angles.h"
#include "model/motion_channels.h"

#include <QAbstractListModel>

#include <array>

namespace gyre::app {

class ChannelListModel : public QAbstractListModel {
    Q_OBJECT

public:
    explicit ChannelListModel(QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    bool setData(const QModelIndex& index, const QVariant& value, int role) override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

    bool isShown(model::Channel channel) const { return shown_[static_cast<std::size_t>(channel)]; }
    void setShown(model::Channel channel, bool shown);
    // The row's name, as the list and the plot's legend give it: "Euler z (°)", "ω x (rad/s)".
    QString name(model::Channel channel) const;
    void setConvention(const EulerConvention& convention);
    QModelIndex indexOf(model::Channel channel) const { return index(static_cast<int>(channel)); }

signals:
    void shownChanged(gyre::model::Channel channel, bool shown);

private:
    EulerConvention convention_;
    // The Euler angles show at first: what an animator reads rotation curves in.
    std::array<bool, model::kChannelCount> shown_{true, true, true};
};

} // namespace gyre::app
