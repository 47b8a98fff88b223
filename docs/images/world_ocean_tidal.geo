// The World Ocean of examples/world_ocean.geo with the physical wavelength reading in
// place of the paper's f1 (docs/fields.md, "Physical criteria"): the tidal wavelength
// T sqrt(g H) / N of stdlib/ocean_fields.geo's TidalWavelength, clamped at the shore
// criterion's 30 km so that the two meshes differ only in where the depth refines.
// docs/images/make_pictures.sh draws it beside the example, both coloured by size.
TidalSizeMin = 30e3;
Include "../../examples/world_ocean.geo";
Call TidalWavelength;
OceanFields[] = {ShoreField, TidalField, HessianField};
Call OceanSize;
