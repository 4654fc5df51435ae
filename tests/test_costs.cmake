# The longest tests, started first by `ctest -j` on a build that has no timing history yet
# (a fresh clone: CTest otherwise runs them in list order, and one of them starting last
# leaves a core idle for its whole run). Seconds measured on 2 cores (docs/performance.md,
# "The test suite"); later runs use CTest's own record (Testing/Temporary/CTestCostData.txt).
# A name no longer in the suite is ignored.
set_tests_properties(KitStudent.TarballHasNoSolutionBuildsAndRunsEveryDocumentedCommand PROPERTIES COST 82)
set_tests_properties(ReadmeCommands.EveryReadmeAndHandoutCommandRunsAsWritten PROPERTIES COST 70)
set_tests_properties(CatalogueGrade.MutantsLoseOnlyOnTheirStageAlternativesScoreFull PROPERTIES COST 65)
set_tests_properties(KitGradescope.SetupAndRunAutograderGradeACorrectSubmissionToFullMarks PROPERTIES COST 19)
set_tests_properties(FairnessGrade.EitherFilterGivesTheFilterPointsToTheImplementedOne PROPERTIES COST 16)
set_tests_properties(SatPrecision.NaiveFloatTableFailsFarFromTheOriginOffsetTableDoesNot PROPERTIES COST 14)
set_tests_properties(Grader.ReferenceScoresFullOnEveryStageLive PROPERTIES COST 14)
set_tests_properties(Study.ResumesAndRedoesOnlyMissingRows PROPERTIES COST 12)
set_tests_properties(Grader.StudentStubsScoreZeroAsNotImplemented PROPERTIES COST 12)
set_tests_properties(Study.PlotsAndPageOpenInHeadlessChromium PROPERTIES COST 10)
set_tests_properties(HostileTimeouts.TheLimitFollowsTheReferenceAndATimeoutIsNotRepeated PROPERTIES COST 10)
set_tests_properties(Grader.CommittedGoldensMatchALiveReferenceRender PROPERTIES COST 10)
