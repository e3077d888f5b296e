# Measured seconds of the suite's slowest tests (ctest --preset ci on 2 cores, Mesa llvmpipe, a clean clone),
# read by ctest as each test's COST: ctest -j2 starts the most costly first, so that a long test does not
# begin near the end while the other worker has nothing left to run. A test not listed costs 0 and fills
# the gaps, and a name no longer in the suite is ignored. Only the order changes; a figure that drifts costs
# a little time, never a result.
# (tests/CMakeLists.txt adds this file to the tests' include files, after the discovered tests.)
set(viz_test_costs
    "CliTest.ReportAt640x480ComparesAtTheErrorTargetsFromItsOwnRows" 190
    "IvsvTest.OpenSkyStaysLitAfterPushPull" 69
    "StabilisingOptions.EachLowersItsTechniquesTemporalError" 68
    "CliTest.EveryBuiltinSceneRendersWithEveryTechnique" 57
    "CliTest.EveryLessonExportsAPageWithAllItsImages" 41
    "ReadBackTest.ARunWithoutReadBackReturnsNoImagesAndPublishesTheSameDeclaredViews" 20
    "IvsvTest.EpipoleRuleAgainstTheReferenceOnAndOff" 32
    "GuiTemporalReference.TheComparisonGridPlaysTheCameraPathAndScoresEachTilesFlicker" 25
    "PolyvolNearLight.PixelPassingTheApexMatchesTheReferenceAndAQuadrature" 24
    "ReportTemporalTest.QuickWritesFiniteTemporalFiguresForEveryTechniqueWithFlickerMaps" 23
    "CliTest.ExportSceneRoundTripRendersTheSameImage" 22
    "MinmaxTest.EpipoleCasesStayFiniteAndAccurate" 21
    "MinmaxIntegrandTest.AutoTakesSvdWhereItStaysWithinTheBoundAndAnalyticWhereSvdWouldBeWorse" 20
    "GuiSceneFile.ADifferenceViewFollowsAReloadThatMovedGeometry" 18
    "GuiSceneFile.AFileChangedOnDiskIsReloadedKeepingTheCamera" 18
    "PolyvolLut.MatchesAnIndependentQuadratureOnRaysPassingTheLight" 15
    "AirlightPointSegment.DoubleMatchesBoostQuadratureOnStiffGrid" 14
    "MinmaxPointTest.MatchesTheReferenceOnPointLightScenes" 13
    "MinmaxEpipolar.SlicesKeepThePromisedGapAt1280x960ByBruteForce" 12
    "GuiViews.TheLightGizmoTurnsAndMovesTheLightAndADividerMovesItsSplit" 12
    "IvsvTest.ReducedGathersStayCloseToTheFullGather" 11
    "CliTest.TheStiffSuiteRunsEveryCaseAndExitsCleanly" 11
    "IvsvTest.InterleavedGatherIsWithinTwoPercentAtTwiceTheResolution" 11
    "CliTest.BadInputIsAOneLineErrorWithExitCode2AndNoOutput" 10
    "PolyvolTest.AdaptiveTessellationMatchesStaticWithFewerTriangles" 9
    "RaymarchTest.ExactIntegrationBeatsTheMidpointRuleAtEqualSamples" 9
    "MinmaxPrefixTest.AutoTakesLog2PassesWhereASequentialRowWouldPassTheLoopLimit" 9
    "LessonPlayer.EveryStepOfLessonsOneAndTwoAppliesInTheWindow" 8
    "PolyvolTest.AdaptiveTessellationFollowsCurvedReceivers" 8
    "MinmaxPointTest.SpotAndPointTogetherAndSvdAndForcedFeatures" 8
    "LessonPlayer.ACompareStepTimesItsTechniquesLiveAndALaterStepClosesTheGrid" 8
    "AnimateTest.BadPathOrFrameCountIsAOneLineErrorAndNoFile" 7
    "GuiAnimation.TheComparisonGridPlaysEveryTechniqueSideBySide" 6
    "CliTest.BadAnimationsNameTheFileAndLine" 6
    "MinmaxPrefixTest.Log2PassesGiveTheSequentialScanWithinRounding" 6
    "GuiCli.PickingASceneWithTheComparisonGridOpenDrawsNoReleasedTexture" 6
    "MeshViewRender.PolyvolAndSlicesDrawTheirMeshesWithTheCameraAndLight" 6
    "IvsvTest.ErrorAgainstTheReferenceFallsWithTheVplCount" 5
    "PolyvolTest.CrackDetectorFindsNoHoleWithAdaptiveTessellation" 5
    "GuiCli.TheComparisonGridShowsEveryTechniqueWithItsErrorAndTime" 5
    "MinmaxTest.LowRankIntegrandMatchesRaymarch" 5
    "ReportTemporalTest.ReferenceFramesAreCachedPerPoseAndReused" 5
    "PolyvolTest.AgreesWithRaymarchOnTheSameMeshReconstruction" 5
    "PolyvolTest.MatchesTheReferenceOnGrate" 5
    "MotionPathRender.AFrameGivesTheSamePixelsHoweverItIsReached" 4
    "CliTest.BenchWritesPerStageTimesFitsAndPlotsForEachAxis" 4
    "VsvTest.EpipoleRulesAgainstTheReferenceOnAndOff" 4
    "PolyvolTest.VolumeFacesBeforeTheNearPlaneStillCount" 4
    "LessonPlayer.ASubstepAnimationOfTheWalkEndsOnItsLastNode" 4
    "MinmaxIntegrandTest.BlendingBetweenSlicesRemovesTheSpotTablesSliceError" 4
    "GuiCli.SteppingMinmaxsWalkEndsOnThePickedRaysLastNode" 4
)
list(LENGTH viz_test_costs n)
math(EXPR last "${n} - 1")
foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET viz_test_costs ${i} name)
    list(GET viz_test_costs ${j} seconds)
    set_tests_properties("${name}" PROPERTIES COST ${seconds})
endforeach()
