# A clean clone has no ctest cost history (build/Testing/Temporary/CTestCostData.txt), so ctest starts
# the tests in the order they were declared, and the longest ones, declared last, end the run alone
# (CI, 2026-11-28: tiles_slurm started 12 minutes in and ran 3.5 minutes after all else). Their costs
# (seconds on 2 cores; the tests of tests/*/CMakeLists.txt set theirs there) make ctest start them first.
# Included by ctest after the gtest_discover_tests lists (TEST_INCLUDE_FILES in CMakeLists.txt).
set_tests_properties(SamAmgRun.StrictMatchesReference PROPERTIES COST 180)
set_tests_properties(RunCli.TinyModelsRunEveryStageOnTheBundledExampleAndASecondRunReusesThem PROPERTIES COST 160)
set_tests_properties(Pix4dLens.PhotosWithR3LoadAsTheRendersAndTrain PROPERTIES COST 40)
