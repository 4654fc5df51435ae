# The longest tests, started first by `ctest -j` on a build that has no timing history yet
# (a fresh clone: CTest otherwise runs them in list order, and one of them starting last
# leaves a core idle for its whole run). Seconds measured on 2 cores (docs/performance.md,
# "The test suite"); later runs use CTest's own record (Testing/Temporary/CTestCostData.txt).
# A name no longer in the suite is ignored.
set(longest_tests
  KitStudent.TarballHasNoSolutionBuildsAndRunsEveryDocumentedCommand 82
  ReadmeCommands.EveryReadmeAndHandoutCommandRunsAsWritten 70
  CatalogueGrade.MutantsLoseOnlyOnTheirStageAlternativesScoreFull 65
  KitGradescope.SetupAndRunAutograderGradeACorrectSubmissionToFullMarks 19
  FairnessGrade.EitherFilterGivesTheFilterPointsToTheImplementedOne 16
  SatPrecision.NaiveFloatTableFailsFarFromTheOriginOffsetTableDoesNot 14
  Grader.ReferenceScoresFullOnEveryStageLive 14
  Study.ResumesAndRedoesOnlyMissingRows 12
  Grader.StudentStubsScoreZeroAsNotImplemented 12
  Study.PlotsAndPageOpenInHeadlessChromium 10
  HostileTimeouts.TheLimitFollowsTheReferenceAndATimeoutIsNotRepeated 10
  Grader.CommittedGoldensMatchALiveReferenceRender 10)
while(longest_tests)
  list(POP_FRONT longest_tests name seconds)
  set_tests_properties(${name} PROPERTIES COST ${seconds})
endwhile()
