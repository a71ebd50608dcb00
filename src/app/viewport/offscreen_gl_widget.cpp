#include "app/viewport/offscreen_gl_widget.h"

#include <QOpenGLFunctions>
#include <QPainter>

namespace gyre::app {

OffscreenGlWidget::OffscreenGlWidget(const QSurfaceFormat& format, QWidget* parent)
    : QWidget(parent)
    , format_(format)
{
    // Every paint covers the widget with the frame: Qt need not clear it first.
    setAttribute(Qt::WA_OpaquePaintEvent);
    setAttribute(Qt::WA_NoSystemBackground);
}

OffscreenGlWidget::~OffscreenGlWidget()
{
    if (context_ && makeCurrent()) {
        framebuffer_.reset();
        doneCurrent();
    }
}

bool OffscreenGlWidget::makeCurrent()
{
    if (!context_ && failure_.isEmpty()) {
        surface_.setFormat(format_);
        surface_.create();
        auto context = std::make_unique<QOpenGLContext>();
        context->setFormat(format_);
        if (!surface_.isValid())
            failure_ = tr("The display could not make an offscreen surface for OpenGL.");
        else if (!context->create())
            failure_ = tr("The display could not make an OpenGL %1.%2 context.")
                           .arg(format_.majorVersion())
                           .arg(format_.minorVersion());
        else if (!context->makeCurrent(&surface_))
            failure_ = tr("The display could not make its OpenGL context current.");
        if (!failure_.isEmpty()) {
            qWarning("%s: %s", metaObject()->className(), qPrintable(failure_));
            return false;
        }
        context_ = std::move(context);
        initializeGL();
    }
    if (!context_ || !context_->makeCurrent(&surface_))
        return false;
    if (framebuffer_ && framebuffer_->isValid())
        framebuffer_->bind();
    return true;
}

void OffscreenGlWidget::doneCurrent()
{
    if (context_)
        context_->doneCurrent();
}

bool OffscreenGlWidget::render()
{
    if (!makeCurrent())
        return false;
    const QSize pixels = (QSizeF(size()) * devicePixelRatioF()).toSize().expandedTo(QSize(1, 1));
    if (!framebuffer_ || framebuffer_->size() != pixels) {
        // Asked for once a size: a refused one is not asked for again at every frame.
        framebuffer_ = std::make_unique<QOpenGLFramebufferObject>(pixels, QOpenGLFramebufferObject::CombinedDepthStencil);
        if (framebuffer_->isValid()) {
            failure_.clear();
            framebuffer_->bind();
            image_ = QImage(pixels, QImage::Format_RGB32);
        } else {
            failure_ = tr("OpenGL could not make a framebuffer of %1 × %2 pixels.").arg(pixels.width()).arg(pixels.height());
            qWarning("%s: %s", metaObject()->className(), qPrintable(failure_));
        }
    }
    if (!framebuffer_->isValid()) {
        doneCurrent();
        return false;
    }
    QOpenGLFunctions* gl = context_->functions();
    gl->glViewport(0, 0, pixels.width(), pixels.height());
    paintGL();
    // BGRA packed as 8_8_8_8_REV is Format_RGB32's 0xffRRGGBB word on any machine, read without conversion;
    // OpenGL's rows run bottom to top.
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl->glReadPixels(0, 0, pixels.width(), pixels.height(), GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, image_.bits());
    image_.mirror();
    image_.setDevicePixelRatio(devicePixelRatioF());
    doneCurrent();
    return true;
}

void OffscreenGlWidget::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    if (render()) {
        painter.drawImage(QPointF(0.0, 0.0), image_);
        return;
    }
    painter.fillRect(rect(), palette().window());
    painter.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, failure_);
}

QImage OffscreenGlWidget::grabFramebuffer()
{
    return render() ? image_.copy() : QImage();
}

} // namespace gyre::app
