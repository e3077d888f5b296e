# Measured seconds of the suite's slowest tests (ctest --preset ci on 2 cores, Mesa llvmpipe, a clean clone),
# read by ctest as each test's COST: ctest -j2 starts the most costly first, so that a long test does not
# begin near the end while the other worker has nothing left to run. A test not listed costs 0 and fills
# the gaps, and a name no longer in the suite is ignored. Only the order changes; a figure that drifts costs
# a little time, never a result.
# (tests/CMakeLists.txt adds this file to the tests' include files, after the discovered tests.)
set(viz_test_costs
    "CliTest.ReportAt640x480ComparesAtTheErrorTargetsFromItsOwnRows" 103
    "Soak.MemoryFilesAndGlObjectsStayFlatAfterWarmUp" 94
    "IvsvTest.OpenSkyStaysLitAfterPushPull" 64
    "StabilisingOptions.EachLowersItsTechniquesTemporalError" 55
    "IvsvTest.ErrorAgainstTheReferenceFallsWithTheVplCount" 34
    "CliTest.EveryBuiltinSceneRendersWithEveryTechnique" 34
    "IvsvTest.EpipoleRuleAgainstTheReferenceOnAndOff" 31
    "CliTest.EveryLessonExportsAPageWithAllItsImages" 27
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/tv_room" 19
    "ReadBackTest.ARunWithoutReadBackReturnsNoImagesAndPublishesTheSameViews" 18
    "MinmaxTest.EpipoleCasesStayFiniteAndAccurate" 17
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/polyvol" 15
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/reference" 15
    "ReportTemporalTest.QuickWritesFiniteTemporalFiguresForEveryTechniqueWithFlickerMaps" 15
    "PolyvolLut.MatchesAnIndependentQuadratureOnRaysPassingTheLight" 14
    "GuiTemporalReference.TheComparisonGridPlaysTheCameraPathAndScoresEachTilesFlicker" 14
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_intensity_1e7" 12
    "AirlightPointSegment.DoubleMatchesBoostQuadratureOnStiffGrid" 12
    "CliTest.ExportSceneRoundTripRendersTheSameImage" 12
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_ray_near_light" 11
    "GuiSceneFile.AFileChangedOnDiskIsReloadedKeepingTheCamera" 11
    "GuiSceneFile.ADifferenceViewFollowsAReloadThatMovedGeometry" 10
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/raymarch" 9
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_occluder_touching_light" 9
    "PolyvolNearLight.PixelPassingTheApexMatchesTheReferenceAndAQuadrature" 9
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/ivsv" 9
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/minmax" 9
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/slices" 8
    "MinmaxPointTest.MatchesTheReferenceOnPointLightScenes" 8
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_extinction_50" 7
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/vsv" 7
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_extinction_1e_6" 7
    "MinmaxEpipolar.SlicesKeepThePromisedGapAt1280x960ByBruteForce" 7
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/grate" 7
    "GuiViews.TheLightGizmoTurnsAndMovesTheLightAndADividerMovesItsSplit" 7
    "CliTest.TheStiffSuiteRunsEveryCaseAndExitsCleanly" 6
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_camera_in_lit_volume" 6
    "IvsvTest.InterleavedGatherIsWithinTwoPercentAtTwiceTheResolution" 6
    "CliTest.BadInputIsAOneLineErrorWithExitCode2AndNoOutput" 6
    "LessonPlayer.EveryStepOfLessonsOneAndTwoAppliesInTheWindow" 6
    "MinmaxPointTest.SpotAndPointTogetherAndSvdAndForcedFeatures" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_hg_minus_0_99" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/terrain" 5
    "GuiCli.TheComparisonGridShowsEveryTechniqueWithItsErrorAndTime" 5
    "GuiAnimation.TheComparisonGridPlaysEveryTechniqueSideBySide" 5
    "CliTest.BenchWritesPerStageTimesFitsAndPlotsForEachAxis" 5
    "PolyvolTest.AdaptiveTessellationMatchesStaticWithFewerTriangles" 5
    "IvsvTest.ReducedGathersStayCloseToTheFullGather" 5
    "RaymarchTest.ExactIntegrationBeatsTheMidpointRuleAtEqualSamples" 5
    "GuiCli.PickingASceneWithTheComparisonGridOpenDrawsNoReleasedTexture" 5
    "MeshViewRender.PolyvolAndSlicesDrawTheirMeshesWithTheCameraAndLight" 4
    "CliTest.BadAnimationsNameTheFileAndLine" 4
    "Cases/StiffSuite.EveryTechniqueStaysFiniteAndWithinItsDeclaredBound/ray_near_light" 4
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/colonnade" 4
    "Cases/StiffSuite.EveryTechniqueStaysFiniteAndWithinItsDeclaredBound/ray_through_light" 4
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/forest" 4
    "AnimateTest.BadPathOrFrameCountIsAOneLineErrorAndNoFile" 4
    "LessonPlayer.ACompareStepTimesItsTechniquesLiveAndALaterStepClosesTheGrid" 4
)
list(LENGTH viz_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET viz_test_costs ${i} name)
    list(GET viz_test_costs ${j} seconds)
    set_tests_properties("${name}" PROPERTIES COST ${seconds})
endforeach()
