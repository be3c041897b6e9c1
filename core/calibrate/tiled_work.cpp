#include "core/calibrate/tiled_work.h"

namespace tp {

void addTiledWork(RendererStats& s, const TiledCounts& c) {
    using Base = PassLightWork::Base;
    using Kind = PassOpWork::Kind;
    if (c.samples > 1 && c.edgePixels > 0)
        s.lightWork.push_back(
            {c.pass, Base::Items, c.meanLights, false,
             "lights_per_tile_mean, per MSAA edge sample beyond the pixel's first",
             c.edgePixels * double(c.samples - 1)});
    s.opWork.push_back({c.pass, Kind::SharedAtomics, Base::Items, 1.0, false,
                        "at least: one per light a tile keeps, one per edge pixel",
                        c.keptLights + c.edgePixels});
    s.opWork.push_back({c.pass, Kind::TileTests, Base::Items, 1.0, false,
                        "at most: every tile's candidates (a tile without geometry tests none)",
                        c.candidates});
}

} // namespace tp
