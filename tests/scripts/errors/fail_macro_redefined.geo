Macro M
Return
Macro M
Return
// expect error: 3:1: macro-redefined
