Include "does_not_exist.inc";
// expect error: 1:9: include-not-found
