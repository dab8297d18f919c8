// Drawing a picture object: its mesh's triangles carry the picture's pixels wherever the mesh
// is posed (a software rasteriser; issue 51).
//
// Every target pixel whose centre lies inside a triangle (after `view`) takes the texture
// sampled at that point's uv, interpolated affinely over the triangle on the target; the pixel is
// composited source-over. Coverage follows the top-left rule on exact fixed-point edge
// functions (1/256 px), so a pixel centre on an edge shared by two triangles belongs to exactly
// one of them: no cracks and no seam blended twice. Triangles are drawn whichever way they wind
// (a folded pose shows both layers), in the order of F. A large draw is split into two bands
// of rows drawn by two threads at once (the calling thread and one more); each pixel still
// sees its triangles in the same order, so the result does not depend on the split.
//
// The mesh's outer boundary is hard: pixels whose centre is outside every triangle are left
// alone. The soft edge of a picture comes from its own alpha, so the mesh should cover all of
// the picture's non-transparent pixels with a margin of a pixel or two (a shape traced at a
// threshold, alpha_outline.h, lies inside the faint fringe of an anti-aliased edge; mesh it
// grown by about 2 px, or the fringe is cut off).
#pragma once

#include <QImage>
#include <QTransform>

#include <Eigen/Core>

namespace finbook::model {

// The pixel kernels drawTexturedMesh can draw with. They give the same pixels bit for bit;
// the wide ones sample and composite 4 (SSE2) or 8 (AVX2) neighbouring pixels at once where
// all of them sample inside the texture. Automatic takes the widest the build and the
// processor have.
enum class TexturedMeshKernel { Automatic, Scalar, Sse2, Avx2 };

// Whether `kernel` can run here (Automatic and Scalar always can).
bool texturedMeshKernelAvailable(TexturedMeshKernel kernel);

// target: Format_ARGB32_Premultiplied (converted in place when it is not).
// view: canvas pixels → target pixels (affine or projective: each vertex is mapped, the
//   triangle between them is straight on the target).
// texture: Format_ARGB32_Premultiplied (others are converted, a copy per call).
// uv: n×2, texture pixels per vertex; (0, 0) is the texture's top-left corner and pixel (i, j)
//   covers [i, i+1] × [j, j+1]. Sampling is bilinear between pixel centres, clamped to the edge
//   pixels inside [0, w] × [0, h]; outside that rectangle the texture is transparent.
// V: n×2 posed vertex positions in canvas pixels. F: m×3 vertex indices into V and uv.
// opacity in [0, 1] scales the texture's premultiplied colour.
// kernel: an unavailable one draws as Automatic.
// Skipped without harm: faces with an index out of range, a non-finite V or uv, zero area on
// the target, or a vertex farther than 2^21 px from the target's origin after `view`; faces
// wholly off the target cost only their bounding-box test. At rest (V == uv, identity view,
// opacity 1, a transparent target) the texture is reproduced exactly where the mesh covers it.
void drawTexturedMesh(QImage &target, const QTransform &view, const QImage &texture,
                      const Eigen::MatrixX2d &uv, const Eigen::MatrixX2d &V,
                      const Eigen::MatrixX3i &F, double opacity = 1.0,
                      TexturedMeshKernel kernel = TexturedMeshKernel::Automatic);

// F in the order drawTexturedMesh draws fastest: by bands of rows of V (32 px, as it draws),
// left to right within a band, so that triangles drawn one after another share their texels and
// target pixels while those are in the cache (a mesher's own order jumps about the picture, and
// an opaque megapixel picture then waits on memory). The same triangles; their order shows only
// where a pose folds the mesh over itself. Rows of F out of range keep their place at the end.
Eigen::MatrixX3i drawingOrder(const Eigen::MatrixX2d &V, const Eigen::MatrixX3i &F);

} // namespace finbook::model
