# Measured seconds of the suite's slowest tests (ctest --preset ci -E Soak on 2 cores, Mesa llvmpipe, an empty
# reference cache, 2026-11-29; those of 4 s and more),
# read by ctest as each test's COST: ctest -j2 starts the most costly first, so that a long test does not
# begin near the end while the other worker has nothing left to run. A test not listed costs 0 and fills
# the gaps, and a name no longer in the suite is ignored. Only the order changes; a figure that drifts costs
# a little time, never a result. Estimated after the open-sky ivsv test moved to 80 x 60 (15 s alone): it, and
# ivsv's error-against-VPL-count test, which now computes tv-room's reference at 160 x 120 (26 s) itself;
# and after the report test moved from 640 x 480 (222 s) to 320 x 240 (31 s alone, about 55 beside another)
# and the stabilising options' reference went to 2 x 2 cells (57 s alone to 39 s, about 70 beside another);
# the tv-room report test measured alone, 32 s, after its sweep took the VPL counts at two march lengths.
# (tests/CMakeLists.txt adds this file to the tests' include files, after the discovered tests.)
set(viz_test_costs
    "StabilisingOptions.EachLowersItsTechniquesTemporalError" 70
    "CliTest.EveryLessonExportsAPageWithAllItsImages" 58
    "CliTest.ReportAboveTheDefaultSizeComparesAtTheErrorTargetsFromItsOwnRows" 55
    "IvsvTest.EpipoleRuleAgainstTheReferenceOnAndOff" 5
    "CliTest.EveryBuiltinSceneRendersWithEveryTechnique" 45
    "IvsvTest.ErrorAgainstTheReferenceFallsWithTheVplCount" 37
    "GuiTemporalReference.TheComparisonGridPlaysTheCameraPathAndScoresEachTilesFlicker" 32
    "ReportTemporalTest.AnAreaLightAddsVplsToTheSweepsOffThePath" 32
    "IvsvTest.OpenSkyStaysLitAfterPushPull" 30
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/tv_room" 29
    "MinmaxTest.EpipoleCasesStayFiniteAndAccurate" 28
    "bundle_test" 27
    "ReportTemporalTest.QuickWritesFiniteTemporalFiguresForEveryTechniqueWithFlickerMaps" 27
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/polyvol" 26
    "ReadBackTest.ARunWithoutReadBackReturnsNoImagesAndPublishesTheSameDeclaredViews" 24
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_intensity_1e7" 22
    "IvsvTest.InterleavedGatherIsWithinTwoPercentAtTwiceTheResolution" 21
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_ray_near_light" 21
    "MinmaxIntegrandTest.AutoTakesSvdWhereItStaysWithinTheBoundAndAnalyticWhereSvdWouldBeWorse" 19
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/reference" 18
    "PolyvolLut.MatchesAnIndependentQuadratureOnRaysPassingTheLight" 17
    "PolyvolNearLight.PixelPassingTheApexMatchesTheReferenceAndAQuadrature" 17
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_occluder_touching_light" 17
    "IvsvTest.ReducedGathersStayCloseToTheFullGather" 17
    "GuiSceneFile.ADifferenceViewFollowsAReloadThatMovedGeometry" 16
    "GuiSceneFile.AFileChangedOnDiskIsReloadedKeepingTheCamera" 15
    "MinmaxEpipolar.SlicesKeepThePromisedGapAt1280x960ByBruteForce" 14
    "AirlightPointSegment.DoubleMatchesBoostQuadratureOnStiffGrid" 13
    "CliTest.TheStiffSuiteRunsEveryCaseAndExitsCleanly" 12
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_extinction_50" 12
    "GuiViews.TheLightGizmoTurnsAndMovesTheLightAndADividerMovesItsSplit" 12
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/minmax" 11
    "MinmaxPointTest.MatchesTheReferenceOnPointLightScenes" 11
    "MinmaxPrefixTest.AutoTakesLog2PassesWhereASequentialRowWouldPassTheLoopLimit" 11
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_hg_minus_0_99" 11
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/slices" 11
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/ivsv" 10
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_camera_in_lit_volume" 10
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/grate" 10
    "PolyvolTest.AdaptiveTessellationMatchesStaticWithFewerTriangles" 10
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/raymarch" 10
    "RaymarchTest.ExactIntegrationBeatsTheMidpointRuleAtEqualSamples" 10
    "Cases/StiffSuite.EveryTechniqueStaysFiniteAndWithinItsDeclaredBound/ray_near_light" 9
    "Techniques/GuiColourBar.EveryImageViewOnEveryBuiltInSceneHasAColourBarWithTicksInsideItsRange/vsv" 9
    "Cases/StiffSuite.EveryTechniqueStaysFiniteAndWithinItsDeclaredBound/ray_through_light" 8
    "PolyvolTest.AdaptiveTessellationFollowsCurvedReceivers" 8
    "MeshViewRender.PolyvolAndSlicesDrawTheirMeshesWithTheCameraAndLight" 7
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/terrain" 7
    "ReportTemporalTest.ReferenceFramesAreCachedPerPoseAndReused" 7
    "IvsvTest.DeinterleavedGatherWritesWhatScreenOrderWrites" 7
    "LessonPlayer.ACompareStepTimesItsTechniquesLiveAndALaterStepClosesTheGrid" 7
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/colonnade" 7
    "PolyvolTest.AgreesWithRaymarchOnTheSameMeshReconstruction" 7
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_ray_through_light" 6
    "MinmaxPointTest.SpotAndPointTogetherAndSvdAndForcedFeatures" 6
    "MinmaxTest.LowRankIntegrandMatchesRaymarch" 6
    "MinmaxPrefixTest.Log2PassesGiveTheSequentialScanWithinRounding" 6
    "CliTest.ExportSceneRoundTripRendersTheSameImage" 6
    "LessonPlayer.EveryStepOfLessonsOneAndTwoAppliesInTheWindow" 6
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_scale_1e4" 6
    "CliTest.BadAnimationsNameTheFileAndLine" 6
    "PolyvolTest.CrackDetectorFindsNoHoleWithAdaptiveTessellation" 6
    "PolyvolTest.VolumeFacesBeforeTheNearPlaneStillCount" 6
    "GuiCli.TheComparisonGridShowsEveryTechniqueWithItsErrorAndTime" 5
    "PolyvolTest.MatchesTheReferenceUnderAColouredCookie" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_hg_0_99" 5
    "GuiCli.PickingASceneWithTheComparisonGridOpenDrawsNoReleasedTexture" 5
    "PolyvolTest.MatchesTheReferenceOnGrate" 5
    "GuiAnimation.TheComparisonGridPlaysEveryTechniqueSideBySide" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/forest" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_light_behind_camera" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_sun_along_view" 5
    "MinmaxIntegrandTest.BlendingBetweenSlicesRemovesTheSpotTablesSliceError" 5
    "VsvTest.EpipoleRulesAgainstTheReferenceOnAndOff" 5
    "MotionPathRender.AFrameGivesTheSamePixelsHoweverItIsReached" 5
    "VsvTest.ForcingSceneFeaturesLeavesTheImageUnchanged" 5
    "IvsvTest.TheInterleavedGatherTakesExactlyThePixelsSubset" 5
    "GuiCli.DraggingAnOrbitViewTurnsItsCamera" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_degenerate_triangles" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_sun_against_view" 5
    "MeshViewRender.PolyvolDrawsItsOrbitViewWhenTheCallerShowsTheMesh" 5
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_camera_in_occluder" 4
    "LessonPlayer.TryItChangesAreUndoneByBackAndByLeavingTryIt" 4
    "EveryScene/WindowFuzz.RandomActionsNeitherAbortNorRaiseGlErrorsNorPutNaNInTheState/stiff_grazing_sun" 4
    "PolyvolTest.TheOrbitViewOfTheMeshStaysInsideTheScenesBox" 4
    "LessonPlayer.ASubstepAnimationOfTheWalkEndsOnItsLastNode" 4
    "SlicesTest.PointLightsUseCameraFrustumPlanesAndConverge" 4
)
list(LENGTH viz_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET viz_test_costs ${i} name)
    list(GET viz_test_costs ${j} seconds)
    set_tests_properties("${name}" PROPERTIES COST ${seconds})
endforeach()
