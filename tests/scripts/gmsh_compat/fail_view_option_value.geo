// A view option's value is still evaluated: its mistakes are the script's.
View.Light = undefined_name;   // expect error: 2:14: unknown-variable
