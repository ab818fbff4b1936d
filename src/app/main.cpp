// Placeholder entry point; the command line is built in src/app.
int main() { return 0; }
