Macro Forever
  Call Forever;
Return
Call Forever;
// expect error: 2:3: call-too-deep
