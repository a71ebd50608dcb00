#include "app/graph_editor/channel_list_model.h"

namespace gyre::app {

using model::Channel;

ChannelListModel::ChannelListModel(QObject* parent)
    : QAbstractListModel(parent)
{
}

int ChannelListModel::rowCount(const QModelIndex& parent) const
{
    return parent.isValid() ? 0 : static_cast<int>(model::kChannelCount);
}

QVariant ChannelListModel::data(const QModelIndex& index, int role) const
{
    if (!index.isValid() || index.row() >= rowCount())
        return {};
    const auto channel = static_cast<Channel>(index.row());
    if (role == Qt::DisplayRole)
        return name(channel);
    if (role == Qt::CheckStateRole)
        return isShown(channel) ? Qt::Checked : Qt::Unchecked;
    return {};
}

bool ChannelListModel::setData(const QModelIndex& index, const QVariant& value, int role)
{
    if (!index.isValid() || index.row() >= rowCount() || role != Qt::CheckStateRole)
        return false;
    setShown(static_cast<Channel>(index.row()), value.value<Qt::CheckState>() == Qt::Checked);
    return true;
}

Qt::ItemFlags ChannelListModel::flags(const QModelIndex& index) const
{
    return QAbstractListModel::flags(index) | Qt::ItemIsUserCheckable;
}

void ChannelListModel::setShown(Channel channel, bool shown)
{
    bool& current = shown_[static_cast<std::size_t>(channel)];
    if (current == shown)
        return;
    current = shown;
    const QModelIndex row = indexOf(channel);
    emit dataChanged(row, row, {Qt::CheckStateRole});
    emit shownChanged(channel, shown);
}

QString ChannelListModel::name(Channel channel) const
{
    const auto axis = [](int index) { return QLatin1Char("xyz"[index]); };
    switch (channel) {
    case Channel::EulerFirst:
    case Channel::EulerSecond:
    case Channel::EulerThird:
        return tr("Euler %1 (°)").arg(axis(convention_.axes[static_cast<std::size_t>(model::eulerIndex(channel))]));
    case Channel::QuaternionW:
        return tr("quaternion w");
    case Channel::QuaternionX:
    case Channel::QuaternionY:
    case Channel::QuaternionZ:
        return tr("quaternion %1").arg(axis(static_cast<int>(channel) - static_cast<int>(Channel::QuaternionX)));
    case Channel::AngularVelocityX:
    case Channel::AngularVelocityY:
    case Channel::AngularVelocityZ:
        return tr("ω %1 (rad/s)").arg(axis(static_cast<int>(channel) - static_cast<int>(Channel::AngularVelocityX)));
    case Channel::AngularSpeed:
        return tr("|ω| (rad/s)");
    case Channel::PositionX:
    case Channel::PositionY:
    case Channel::PositionZ:
        return tr("position %1").arg(axis(static_cast<int>(channel) - static_cast<int>(Channel::PositionX)));
    case Channel::AngularMomentumX:
    case Channel::AngularMomentumY:
    case Channel::AngularMomentumZ:
        return tr("L %1 (kg·m²/s)").arg(axis(static_cast<int>(channel) - static_cast<int>(Channel::AngularMomentumX)));
    case Channel::AngularMomentumMagnitude:
        return tr("|L| (kg·m²/s)");
    case Channel::KineticEnergy:
        return tr("rotational energy (J)");
    }
    return {};
}

void ChannelListModel::setConvention(const EulerConvention& convention)
{
    convention_ = convention;
    emit dataChanged(indexOf(Channel::EulerFirst), indexOf(Channel::EulerThird), {Qt::DisplayRole});
}

} // namespace gyre::app
