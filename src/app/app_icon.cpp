#include "app/app_icon.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>
#include <QRadialGradient>

#include <cmath>
#include <numbers>

namespace gyre::app {
namespace {

// The drawing is laid out on a 256-unit square and scaled to the size asked for.
constexpr double kDesignSize = 256.0;
const QPointF kSphereCentre(128.0, 134.0);
constexpr double kSphereRadius = 76.0;
// The orbit: an ellipse around the sphere, tilted so its upper half passes behind it.
constexpr double kOrbitRadiusX = 108.0;
constexpr double kOrbitRadiusY = 36.0;
constexpr double kOrbitTiltDegrees = -18.0;
constexpr double kOrbitWidth = 13.0;
const QColor kOrbitColour(255, 140, 26);

void paintBackground(QPainter& painter)
{
    QLinearGradient gradient(0.0, 0.0, 0.0, kDesignSize);
    gradient.setColorAt(0.0, QColor(60, 80, 104));
    gradient.setColorAt(1.0, QColor(30, 40, 56));
    painter.setPen(Qt::NoPen);
    painter.setBrush(gradient);
    painter.drawRoundedRect(QRectF(8.0, 8.0, kDesignSize - 16.0, kDesignSize - 16.0), 44.0, 44.0);
}

void paintSphere(QPainter& painter)
{
    const QPointF highlight = kSphereCentre + QPointF(-0.35 * kSphereRadius, -0.4 * kSphereRadius);
    QRadialGradient shading(kSphereCentre, kSphereRadius, highlight);
    shading.setColorAt(0.0, QColor(200, 230, 255));
    shading.setColorAt(0.55, QColor(96, 158, 214));
    shading.setColorAt(1.0, QColor(38, 84, 140));
    painter.setPen(Qt::NoPen);
    painter.setBrush(shading);
    painter.drawEllipse(kSphereCentre, kSphereRadius, kSphereRadius);

    // An equator and a meridian, so the ball reads as a globe that turns.
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(255, 255, 255, 110), 3.0));
    painter.drawEllipse(kSphereCentre, kSphereRadius, 0.3 * kSphereRadius);
    painter.drawEllipse(kSphereCentre, 0.42 * kSphereRadius, kSphereRadius);
}

// Qt's arc angles count counter-clockwise from three o'clock in sixteenths of a degree; the point at
// angle θ on the orbit is (a cos θ, −b sin θ) in its own tilted frame.
QPointF orbitPoint(double degrees)
{
    const double theta = degrees * std::numbers::pi / 180.0;
    return {kOrbitRadiusX * std::cos(theta), -kOrbitRadiusY * std::sin(theta)};
}

void paintOrbitArc(QPainter& painter, double fromDegrees, double spanDegrees, const QColor& colour)
{
    painter.setPen(QPen(colour, kOrbitWidth, Qt::SolidLine, Qt::RoundCap));
    painter.setBrush(Qt::NoBrush);
    painter.drawArc(QRectF(-kOrbitRadiusX, -kOrbitRadiusY, 2.0 * kOrbitRadiusX, 2.0 * kOrbitRadiusY),
                    static_cast<int>(fromDegrees * 16.0), static_cast<int>(spanDegrees * 16.0));
}

// The arrowhead at angle `degrees`, pointing the way the angle grows: the tangent there is
// d/dθ (a cos θ, −b sin θ) = (−a sin θ, −b cos θ).
void paintArrowhead(QPainter& painter, double degrees)
{
    const double theta = degrees * std::numbers::pi / 180.0;
    QPointF along(-kOrbitRadiusX * std::sin(theta), -kOrbitRadiusY * std::cos(theta));
    along /= std::hypot(along.x(), along.y());
    const QPointF across(-along.y(), along.x());
    const QPointF base = orbitPoint(degrees);
    QPainterPath head;
    head.moveTo(base + 26.0 * along);
    head.lineTo(base + 17.0 * across);
    head.lineTo(base - 17.0 * across);
    head.closeSubpath();
    painter.setPen(Qt::NoPen);
    painter.setBrush(kOrbitColour);
    painter.drawPath(head);
}

} // namespace

void paintAppIcon(QPainter& painter, double size)
{
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    painter.scale(size / kDesignSize, size / kDesignSize);
    paintBackground(painter);

    painter.save();
    painter.translate(kSphereCentre);
    painter.rotate(kOrbitTiltDegrees);
    paintOrbitArc(painter, 0.0, 180.0, kOrbitColour.darker(160)); // behind the sphere
    painter.restore();

    paintSphere(painter);

    painter.translate(kSphereCentre);
    painter.rotate(kOrbitTiltDegrees);
    paintOrbitArc(painter, 180.0, 150.0, kOrbitColour); // in front, ending at the arrowhead
    paintArrowhead(painter, 330.0);
    painter.restore();
}

QIcon appIcon()
{
    QIcon icon;
    for (const int size : kAppIconSizes) {
        QPixmap pixmap(size, size);
        pixmap.fill(Qt::transparent);
        QPainter painter(&pixmap);
        paintAppIcon(painter, size);
        painter.end();
        icon.addPixmap(pixmap);
    }
    return icon;
}

} // namespace gyre::app
