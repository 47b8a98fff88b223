// The paper's criteria (Lambrechts et al. 2008, section 3.1) on real ETOPO5
// data around the Great Barrier Reef, on a unit sphere. Node values read with
// `ncdump -v z etopo5_gbr_5min.nc`: z(150E, 15S) = -1856,
// z(150.0833E, 15S) = -1776, z(140E, 26S) = 75 (land).
gbr = "../../../data/bathymetry/etopo5_gbr_5min.nc";
d2r = Pi / 180;
Macro Sphere
  px = Cos(lat * d2r) * Cos(lon * d2r);  py = Cos(lat * d2r) * Sin(lon * d2r);  pz = Sin(lat * d2r);
Return

// Depth H = max(-z, MinDepth), bilinear between the nodes.
Field[1] = Bathymetry;
Field[1].FileName = gbr;
lon = 150; lat = -15; Call Sphere;
Printf("%.6g", FieldValue(1, px, py, pz));   // expect: 1856
lon = 150 + 1/24; Call Sphere;
Printf("%.6g", FieldValue(1, px, py, pz));   // expect: 1816
lon = 140; lat = -26; Call Sphere;
Printf("%.6g", FieldValue(1, px, py, pz));   // expect: 10

// The same grid as an ESRI ASCII file (first row north).
Field[10] = Bathymetry;
Field[10].FileName = "../../../data/bathymetry/etopo5_gbr_5min.asc";
lon = 150; lat = -15; Call Sphere;
Printf("%.6g", FieldValue(10, px, py, pz));   // expect: 1856
// The global 1-degree grid across the dateline (float values, as ncdump shows
// them): z(179E, 10S) = -4568.657,
// z(180, 10S) = z(-180, 10S) = -3880.569, z(-179E, 10S) = -4051.445.
Field[11] = Bathymetry;
Field[11].FileName = "../../../data/bathymetry/etopo5_global_1deg.nc";
lon = 179.5; lat = -10; Call Sphere;
Printf("%.2f", FieldValue(11, px, py, pz));   // expect: 4224.61
lon = -179.5; Call Sphere;
Printf("%.2f", FieldValue(11, px, py, pz));   // expect: 3966.01

// f1: gravity-wave wavelength lambda_min/N sqrt(H_ref/H), in metres.
Field[2] = Bathymetry;
Field[2].FileName = gbr;
Field[2].Output = "wavelength";
Field[2].WaveLengthMin = 250e3;
Field[2].PointsPerWaveLength = 10;
Field[2].DepthRef = 4000;
lon = 150; lat = -15; Call Sphere;
Printf("%.6g", FieldValue(2, px, py, pz));   // expect: 36701.3
// ... turned into a size by the paper's clamp (Threshold).
Field[3] = Threshold;
Field[3].InField = 2;
Field[3].SizeMin = 10e3;  Field[3].SizeMax = 100e3;
Field[3].DistMin = 30e3;  Field[3].DistMax = 60e3;
Printf("%.6g", FieldValue(3, px, py, pz));   // expect: 30103.8

// f2: 1/sqrt(|lambda_max|) of the Hessian of H/H_ref (metres), clamped the same way.
Field[4] = Bathymetry;
Field[4].FileName = gbr;
Field[4].Output = "hessian";
Field[5] = Threshold;
Field[5].InField = 4;
Field[5].SizeMin = 10e3;  Field[5].SizeMax = 100e3;
Field[5].DistMin = 30e3;  Field[5].DistMax = 60e3;
f2 = FieldValue(4, px, py, pz);
Assert(f2 > 0 && f2 < 1e22, "f2 = %g", f2);

// f3: distance to the shore, here two coastal points of Queensland.
lon = 146; lat = -19; Call Sphere;
Point(1) = {px, py, pz};
lon = 145.5; lat = -16; Call Sphere;
Point(2) = {px, py, pz};
Field[6] = Distance;
Field[6].PointsList = {1, 2};
Field[7] = Threshold;
Field[7].InField = 6;
Field[7].SizeMin = 5e3 / 6371e3;  Field[7].SizeMax = 100e3 / 6371e3;
Field[7].DistMin = 0;  Field[7].DistMax = 500e3 / 6371e3;
Field[8] = MathEval;
Field[8].F = "F7 * 6371e3";   // sphere units -> metres, like f1 and f2

Field[9] = Min;
Field[9].FieldsList = {3, 5, 8};
Background Field = 9;
lon = 150; lat = -15; Call Sphere;
h = FieldValue(9, px, py, pz);
Assert(h == Min(FieldValue(3, px, py, pz), Min(FieldValue(5, px, py, pz), FieldValue(8, px, py, pz))));
// On the coast the shore criterion wins with its SizeMin.
lon = 146; lat = -19; Call Sphere;
Printf("%.6g %g", FieldValue(9, px, py, pz), FieldArgmin(9, px, py, pz));   // expect: 5000 8
