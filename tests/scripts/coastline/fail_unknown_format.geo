// A misspelt format: the error names the four formats and the closest one.
Coastline[1] = GSHS;
// expect error: 2:16: unknown-coastline-format
