# The longest tests, started first by `ctest -j` on a build that has no timing history yet
# (a fresh clone: CTest otherwise runs them in list order, and one of them starting last
# leaves a core idle for its whole run). Seconds: a fresh clone's run on 2 cores; later runs
# use CTest's own record (Testing/Temporary/CTestCostData.txt).
# A name no longer in the suite is ignored.
set(longest_tests
  KitStudent.TarballHasNoSolutionBuildsAndRunsEveryDocumentedCommand 66
  KitAttack.NoShippedFunctionOrShaderScoresAsAStage 50
  CatalogueGrade.MutantsLoseOnlyOnTheirStageAlternativesScoreFull 106
  CatalogueGrade.ThePackedStudentKitGradesEveryEntryAsTheAutograder 90
  ReadmeCommands.EveryReadmeAndHandoutCommandRunsAsWritten 56
  HostileTimeouts.TheLimitFollowsTheReferenceAndATimeoutIsNotRepeated 18
  HostileTimeouts.ALoopCostsOnlyTheRendersThatRunItsFile 18
  KitGradescope.SetupAndRunAutograderGradeACorrectSubmissionToFullMarks 19
  Grader.CommittedGoldensMatchALiveReferenceRender 15
  FairnessGrade.EitherFilterGivesTheFilterPointsToTheImplementedOne 14
  Grader.ReferenceScoresFullOnEveryStageLive 13
  SatPrecision.NaiveFloatTableFailsFarFromTheOriginOffsetTableDoesNot 8
  InstructorGoldens.HiddenGoldensGoNextToTheirSceneAndThePublicManifestKeepsItsEntries 8
  Study.PlotsAndPageOpenInHeadlessChromium 5
  GraderLimits.InfiniteLoopInMsmTimesOutAndCostsOnlyItsStages 5)
while(longest_tests)
  list(POP_FRONT longest_tests name seconds)
  set_tests_properties(${name} PROPERTIES COST ${seconds})
endwhile()
