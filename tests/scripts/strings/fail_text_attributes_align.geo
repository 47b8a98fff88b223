// Only BottomLeft..CenterRight and the short Left/Center/Right (also in lower
// case) are alignments.
t = TextAttributes("Align", "TOPRIGHT");
// expect error: 3:29: builtin-error
