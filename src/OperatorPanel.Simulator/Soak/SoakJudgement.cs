using System.Collections.Immutable;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// The judge's part of <see cref="SoakFigures"/>: the panel's claims held against what the PLC executed, and the first
/// findings (memory changes nothing explains, writes out of order, wrong values, false confirmations) in words.
/// </summary>
public sealed record SoakJudgement(
    int ValuesShownGood,
    int WrongValuesShownGood,
    int WritesSent,
    int WritesConfirmed,
    int ConfirmedByReadBack,
    int ConfirmedAlreadyHeld,
    int FalseConfirmations,
    int WritesOutOfOrder,
    ImmutableSortedDictionary<string, int> WritesNotConfirmed,
    int NotConfirmedButExecuted,
    int FalseNotApplied,
    int ExecutedNeverSent,
    int FieldChanges,
    ImmutableSortedDictionary<string, int> ShownGoodByItem,
    ImmutableSortedDictionary<string, int> ConfirmedByItem,
    ImmutableArray<string> Findings);
