For i In {1:1e12}
EndFor
// expect error: 1:1: limit-exceeded
