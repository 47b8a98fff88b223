// 10^12 iterations of empty nested loops stop at the statement budget (10^8).
For i In {1:1e4}
  For j In {1:1e4}
    For k In {1:1e4}
    EndFor
  EndFor
EndFor
// expect error: 4:5: limit-exceeded
