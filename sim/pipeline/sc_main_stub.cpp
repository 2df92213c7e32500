// libsystemc.so defines main() and calls sc_main(); girtd has its own main()
// and starts SystemC itself (sim/pipeline), so the library's entry point is
// never used, but must link. Kept out of any file that includes systemc.h
// (which declares sc_main itself). Visible even where symbols are hidden by
// default (the Python module): libsystemc.so resolves it at load time.
extern "C" __attribute__((visibility("default"))) int sc_main(int, char**) { return 0; }
