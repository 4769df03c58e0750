// The scene room of the broken tree.
