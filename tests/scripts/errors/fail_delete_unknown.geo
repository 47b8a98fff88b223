Delete nothing_here;
// expect error: 1:8: delete-unknown-variable
