// A library for PluginLibraryTest: the table a plugin exports, with a value to read back.
struct TestPluginTable {
    int abi;
    int answer;
};

extern "C" __attribute__((visibility("default"))) const TestPluginTable* camwb_test_plugin_table()
{
    static const TestPluginTable table{7, 42};
    return &table;
}
