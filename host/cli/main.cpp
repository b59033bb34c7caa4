#include "cli.hpp"

int main(int argc, char** argv) { return fgr::run_cli(argc, argv); }
