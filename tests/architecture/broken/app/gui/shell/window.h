// A file of the shell room of the broken tree: physics may not include it.
