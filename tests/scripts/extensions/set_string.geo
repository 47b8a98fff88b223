// SetString/GetString (Gmsh 4.8.4's parser has no SetString statement).
SetString("ss", "val");
s = GetString("ss");
Printf(s);  // expect: val
t = GetString("missing", "default");
Printf(t);  // expect: default
// compare_with_gmsh: skip (native behaviour)
