#pragma once
// Snapshot overlay of one scale estimate for viz's drawProjectedScan on image C(i-1): every selected
// keypoint as a ring coloured by the stage that rejected it, its track into C(i) as a segment, and a
// legend with the count per stage. Library vlo::scale_overlay (depends on vlo::viz).
#include <vlo/scale/diagnostics.h>
#include <vlo/viz/projected_scan.h>

namespace vlo::scale
{
/// Okabe-Ito colours, distinct from each other for colour-blind readers.
viz::Rgb stageColor(Stage s);
/// Short legend label of a stage ("inlier" for Stage::None; the overlay says "kept" instead when the
/// estimate stopped before RANSAC).
const char* stageLabel(Stage s);

viz::ImageOverlay scaleOverlay(const ScaleEstimate& e, bool tracks = true);
}  // namespace vlo::scale
