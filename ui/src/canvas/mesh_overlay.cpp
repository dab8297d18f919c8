#include <finbook/deform/arap.h>
#include <finbook/ui/canvas/canvas_widget.h>
#include <finbook/ui/canvas/mesh_overlay.h>
#include <finbook/ui/window/editor_state.h>

#include <QPainter>

namespace finbook::ui {

MeshOverlay::MeshOverlay(EditorState *state, model::DeformController *controller,
                         CanvasWidget *canvas)
    : QObject(canvas)
    , m_state(state)
    , m_controller(controller)
    , m_canvas(canvas)
{
    auto repaint = [this] {
        if (m_state->showMesh())
            m_canvas->update();
    };
    connect(m_controller, &model::DeformController::meshChanged, this, repaint);
    connect(m_controller, &model::DeformController::poseSolved, this, repaint);
    connect(m_state, &EditorState::showMeshChanged, this, [this] {
        requestMissing();
        m_canvas->update();
    });
    connect(m_state, &EditorState::currentFrameChanged, this, [this] { requestMissing(); });
    connect(m_state->document(), &model::Document::strokesChanged, this,
            [this] { requestMissing(); });
}

void MeshOverlay::requestMissing()
{
    const model::Frame *f = m_state->currentFrame();
    if (!m_state->showMesh() || !f)
        return;
    for (const model::StrokeGroup &g : f->groups) {
        const model::DeformSetup *setup = m_controller->setup(g.id);
        const bool current =
            setup && setup->key == model::MeshKey::of(g, m_state->document()->settings().closeGap);
        if (g.visible && g.hasContent() && !current && !m_controller->isWaiting(g.id))
            m_controller->requestMesh(g.id);
    }
}

// Triangles the pose turns inside out, red under the mesh lines: folds the pins force
// (a converged pin pose keeps no other), a cage crossing itself, a drag not yet settled.
void MeshOverlay::paintFolds(QPainter &painter, const QTransform &canvasToWidget,
                             const model::DeformSetup &setup, const Eigen::MatrixX2d &U)
{
    const Eigen::MatrixX3i &F = setup.meshTriangles();
    const std::vector<int> folds = deform::arapFlippedTriangleRows(setup.meshVertices(), F, U);
    if (folds.empty())
        return;
    // Filled, and ringed: a forced fold is often a sliver, or a few triangles round one
    // point, with next to no area at any zoom.
    const QColor red(220, 30, 30);
    painter.save();
    painter.setPen(QPen(red, 1.5));
    painter.setBrush(QColor(220, 30, 30, 170));
    QVector<QPointF> centres;
    centres.reserve(qsizetype(folds.size()));
    for (const int t : folds) {
        QPolygonF triangle;
        for (int k = 0; k < 3; ++k)
            triangle << canvasToWidget.map(QPointF(U(F(t, k), 0), U(F(t, k), 1)));
        painter.drawPolygon(triangle);
        centres.append((triangle[0] + triangle[1] + triangle[2]) / 3.0);
    }
    painter.setPen(QPen(red, 2.0));
    painter.setBrush(Qt::NoBrush);
    for (const QPointF &c : centres)
        painter.drawEllipse(c, 11.0, 11.0); // round a pin dot there too
    painter.restore();
}

void MeshOverlay::paint(QPainter &painter, const QTransform &canvasToWidget)
{
    const model::Frame *f = m_state->currentFrame();
    // A preview frame (the in-between dialog's) is not meshed: its pose is not the document's.
    if (!m_state->showMesh() || !f || m_canvas->hasPreviewFrame())
        return;
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing);
    const model::Id current = m_state->currentGroupId();
    for (const model::StrokeGroup &g : f->groups) {
        const model::DeformSetup *setup = m_controller->setup(g.id);
        if (!g.visible || !setup)
            continue;
        const Eigen::MatrixX2d &U = *m_controller->poseVertices(g.id);
        paintFolds(painter, canvasToWidget, *setup, U);
        QColor colour = g.id == current ? QColor(20, 140, 200, 150) : QColor(120, 120, 120, 110);
        painter.setPen(QPen(colour, 0.8));
        // A cage's interior mesh, or a cut-out skeleton's cut mesh: triangles only.
        if (!setup->meshed || &setup->meshTriangles() != &setup->meshed->mesh.F) {
            const Eigen::MatrixX3i &F = setup->meshTriangles();
            QVector<QLineF> lines;
            lines.reserve(int(F.rows() * 3));
            for (Eigen::Index t = 0; t < F.rows(); ++t)
                for (int k = 0; k < 3; ++k) {
                    const int a = F(t, k), b = F(t, (k + 1) % 3);
                    lines.append(canvasToWidget.map(QLineF(U(a, 0), U(a, 1), U(b, 0), U(b, 1))));
                }
            painter.drawLines(lines);
            continue;
        }
        const geometry::TriMesh &mesh = setup->meshed->mesh.mesh;
        // Each edge once (the OpenMesh mesh's vertex i is row i of V), so shared edges are not
        // drawn twice — half the work on every repaint while a pin is dragged.
        QVector<QLineF> lines;
        lines.reserve(int(mesh.n_edges()));
        for (const auto edge : mesh.edges()) {
            const int a = edge.v0().idx(), b = edge.v1().idx();
            lines.append(canvasToWidget.map(QLineF(U(a, 0), U(a, 1), U(b, 0), U(b, 1))));
        }
        painter.drawLines(lines);
    }
    painter.restore();
}

} // namespace finbook::ui
