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
    if (!context_ && !contextFailed_) {
        surface_.setFormat(format_);
        surface_.create();
        auto context = std::make_unique<QOpenGLContext>();
        context->setFormat(format_);
        if (!surface_.isValid() || !context->create() || !context->makeCurrent(&surface_)) {
            contextFailed_ = true;
            return false;
        }
        context_ = std::move(context);
        initializeGL();
    }
    if (!context_ || !context_->makeCurrent(&surface_))
        return false;
    if (framebuffer_)
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
        framebuffer_ = std::make_unique<QOpenGLFramebufferObject>(pixels, QOpenGLFramebufferObject::CombinedDepthStencil);
        framebuffer_->bind();
        image_ = QImage(pixels, QImage::Format_RGB32);
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
    if (render())
        painter.drawImage(QPointF(0.0, 0.0), image_);
    else
        painter.fillRect(rect(), palette().window());
}

QImage OffscreenGlWidget::grabFramebuffer()
{
    return render() ? image_.copy() : QImage();
}

} // namespace gyre::app
