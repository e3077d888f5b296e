// An included file with a deliberate syntax error (Mesa reports these with the source-string number).
float syntaxHelper(float x) {
    return x  // DELIBERATE ERROR: missing semicolon
}
