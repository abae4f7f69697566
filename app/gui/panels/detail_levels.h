#pragma once

#include <QString>

namespace octaclay::app {

/// The words a newcomer reads for a model's size N (the N×N geometry image): "Detail: Fine
/// (512)". Used by File ▸ New and File ▸ Import Mesh, whose choices are N = 64 … 4096.
QString detailLabel(int n);
/// What N means, for the item's tooltip: "N = 512: 512 × 512 samples, 524,288 triangles".
QString detailTooltip(int n);

} // namespace octaclay::app
