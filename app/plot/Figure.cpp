#include "app/plot/Figure.h"

#include <array>

namespace prisca::app::plot {

QColor paletteColor(int index) {
    static const std::array<QRgb, 10> kPalette = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                                  0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
    const int n = static_cast<int>(kPalette.size());
    return QColor(kPalette[static_cast<std::size_t>(((index % n) + n) % n)]);
}

}  // namespace prisca::app::plot
