// The cage's half of a DeformSetup: harmonic coordinates (Joshi et al. 2007) of the cage's
// interior mesh and every rest stroke point bound to them, so a corner drag is one small
// dense product. Also the checks and the Fit Cage step the Cage tool and commands use.
#pragma once

#include <finbook/deform/cage/harmonic_cage.h>
#include <finbook/model/deform_setup.h>

#include <optional>

namespace finbook::model {

struct CageSetup {
    std::shared_ptr<const deform::CagePrecompute> coordinates;
    deform::CageBinding binding; // every rest stroke point, stroke after stroke

    const Eigen::MatrixX2d &meshVertices() const { return coordinates->mesh.V; }
    const Eigen::MatrixX3i &meshTriangles() const { return coordinates->mesh.F; }
};

// Meshes the cage interior, solves the coordinates and binds the drawing's rest points.
// Errors are sentences: a bad cage, points outside it, cancellation.
Expected<std::shared_ptr<const CageSetup>, QString>
buildCageSetup(const MeshKey &key, const std::vector<QPointF> &corners,
               const std::function<bool()> &cancelled);

struct CageSolution {
    Eigen::MatrixX2d meshVertices; // n×2, the posed interior mesh
    Eigen::MatrixX2d points;       // P×2, the posed rest points
};
// posed: one position per rest corner, in order. Any posed cage works, crossed ones too.
Expected<CageSolution, QString> solveCage(const CageSetup &setup,
                                          const std::vector<QPointF> &posed);

// Why `corners` cannot be a cage around `group`'s drawing, as a sentence; nullopt when it can
// (at least 3 corners, simple, non-zero area, containing every rest stroke point).
std::optional<QString> cageProblem(const StrokeGroup &group, const std::vector<QPointF> &corners);

// Whether a posed cage crosses itself (it still deforms; the editor tints it as a warning).
bool cageCrossesItself(const std::vector<QPointF> &corners);

// Fit Cage: the drawing's shape (its ink and its regions closed at the document's `closeGap`)
// grown and simplified to about `corners` corners (8–24 by default), containing every stroke
// point.
Expected<std::vector<QPointF>, QString> fitCage(const StrokeGroup &group, int corners,
                                                double closeGap = -1.0);

constexpr int kDefaultFitCageCorners = 16;
constexpr int kMinFitCageCorners = 4;
constexpr int kMaxFitCageCorners = 48;

} // namespace finbook::model
