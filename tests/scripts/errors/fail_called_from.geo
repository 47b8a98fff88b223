// The error is located inside the macro; notes point at each Call.
Macro Inner
  v = missing + 1;
Return
Macro Outer
  Call Inner;
Return
Call Outer;
// expect error: 3:7: unknown-variable
