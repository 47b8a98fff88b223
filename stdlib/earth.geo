// Earth constants for ocean scripts (SI units), found through the Include
// search path: `Include "earth.geo";`. DefineConstant lets a script or
// -setnumber choose another radius first.
DefineConstant[ EarthRadius = 6371e3 ];   // mean Earth radius (m), as in Lambrechts et al. 2008
Deg2Rad = Pi / 180;
Rad2Deg = 180 / Pi;
