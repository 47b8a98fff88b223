Macro Build
Return
Call Biuld;
// expect error: 3:1: unknown-macro
