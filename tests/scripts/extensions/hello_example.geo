// examples/hello.geo as a regression test (its Include of earth.geo uses the
// stdlib search path, a native feature). Output identical to gmsh 4.8.4 -0
// when earth.geo is copied next to it.
Include "../../../examples/hello.geo";
// gmsh 4.8.4 -0 output of the example:
// expect: 5 cities, sphere radius 1
// expect: Brest: u = -0.3788, v = 0.0297, |(u,v)| = 0.3800
// expect: Cape Town: u = -1.7814, v = -0.5933, |(u,v)| = 1.8776
// expect: Honolulu: u = 0.6329, v = 0.2575, |(u,v)| = 0.6833
// expect: Reykjavik: u = -0.2129, v = 0.0857, |(u,v)| = 0.2295
// expect: Hobart: u = 1.9305, v = -1.2379, |(u,v)| = 2.2933
// expect: 3 of 5 cities are north of the equator
Printf("%g", EarthRadius);  // expect: 6.371e+06
// compare_with_gmsh: skip (native behaviour)
