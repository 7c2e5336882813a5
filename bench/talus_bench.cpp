int quick_main(int, char**);
int main(int argc, char** argv) { return quick_main(argc, argv); }
