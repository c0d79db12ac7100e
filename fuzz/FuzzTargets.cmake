# The fuzz targets: fuzz/fuzz_<name>.cpp, seeds in fuzz/corpus/<name>, inputs that once crashed
# in fuzz/regressions/<name> (replayed by the test suite).
set(PM_FUZZ_TARGETS photo_model rig camera_xml camera_file pose_table tracker_config image pose_yaml)
