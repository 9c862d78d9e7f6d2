// Where each Haar coefficient of a chart layout sits in the transfer product's input
// (transfer_product.h): an order that keeps one place's coefficients together. The product
// stores its rows (CDF 9/7 coefficients, laid out in the same quadrants) in this order too.
// It changes only speed: any permutation gives the same sums up to float rounding order.
//
// haarForwardCharts leaves each chart's coefficients in the Mallat layout: the three detail
// bands of a level are three distant quadrants, and a place's coefficients at successive
// levels are further apart still. A row of the transfer reads the coarse coefficients of
// every chart and the fine ones around its own output, so in the Mallat layout each fine
// read touches its own cache line. Ordered by (chart, level, Morton index of the
// coefficient's place within its band, band), neighbouring places share lines and the
// three bands of a place sit side by side.
#pragma once

#include "schema/wavelet/chart_layout.h"

#include <cstdint>
#include <vector>

namespace opal {

// slots[j]: the position of Mallat coefficient j (chart j / S^2, row (j mod S^2) / S, column
// j mod S) in the locality order; a permutation of [0, layout.cells()).
std::vector<std::uint32_t> haarLocalitySlots(const ChartLayout& layout);

}  // namespace opal
