// ShoreProximity needs the coast: neither ShorePoints[] nor ShoreCurves[] is an error
// located at the macro's check (line 52 of stdlib/ocean_fields.geo), with the Call as a note.
// compare_with_gmsh: skip (stdlib search path)
Include "ocean_fields.geo";
Call EarthSphere;
Call ShoreProximity;
// expect error: 52:7: user-error
