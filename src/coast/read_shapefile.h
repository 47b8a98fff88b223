// Reader for ESRI shapefiles of shorelines (Polygon, PolygonZ/M, PolyLine, PolyLineZ/M;
// lon/lat degrees) through shapelib.
#pragma once

#include <string>

#include "coast/coastline.h"

namespace sm::coast {

struct ShapefileInfo {
  int shape_type = 0;
  int records = 0;
  bool index_rebuilt = false;   // the .shx was missing and was rebuilt (see read_shapefile)
};

/// Each part of each record becomes one Ring (record = shape index, part = part index).
/// Polygon parts are closed; a PolyLine part is closed when its last point repeats its
/// first. Polygon rings follow the shapefile rule: clockwise parts are outer rings
/// (level 1), counter-clockwise parts are holes (level 2).
/// A missing .shx (GSHHS_l_L1.shp ships without one) is rebuilt by shapelib's
/// SHPRestoreSHX from a sequential scan of the .shp, into a private temporary directory
/// (the data directory may be read-only); the rebuilt index is deleted afterwards.
Result<Coastline> read_shapefile(const std::string& path, ShapefileInfo* info = nullptr);

}  // namespace sm::coast
