// placeholder: filled in by later work
