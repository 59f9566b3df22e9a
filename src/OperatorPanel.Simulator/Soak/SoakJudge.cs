using System.Collections.Immutable;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// Holds the panel's claims (values shown as good, writes confirmed) against what the PLC did as the
/// <see cref="ExecutedWriteObserver"/> saw it, from the watched bytes as they were at the start (<c>initial</c>):
/// every change is named (<see cref="ChangeAttribution"/>), and every address's values over the run
/// (<see cref="ItemHistory"/>) are what a good value shown and a confirmation are checked against. Limits: a byte or
/// bit value recurs, so a wrong byte or bit shown good that equals a value the address held in the same step, and a
/// late byte or bit write equal to the one in flight, pass; words and double words never recur.
/// </summary>
public sealed class SoakJudge(SoakRegion region, MemoryImage initial)
{
    /// <summary>Findings kept for the report: enough to see what went wrong, not a log.</summary>
    private const int FindingsKept = 10;

    /// <summary>
    /// The judgement of a run: <paramref name="changes"/> as the observer saw them, <paramref name="fieldSettings"/> as
    /// the field made them (<see cref="SoakField.Settings"/>; none when nothing drives I and SM).
    /// </summary>
    public SoakJudgement Judge(
        IReadOnlyList<SoakWrite> writes, IReadOnlyList<ShownValue> shown, IReadOnlyList<MemoryChange> changes, IReadOnlyList<MemoryChange> fieldSettings)
    {
        ArgumentNullException.ThrowIfNull(writes);
        ArgumentNullException.ThrowIfNull(shown);
        ArgumentNullException.ThrowIfNull(changes);
        ArgumentNullException.ThrowIfNull(fieldSettings);
        var image = initial.Copy();
        var history = new ItemHistory([.. region.Items, .. writes.Select(w => w.Address), .. shown.Select(v => v.Address)], image);
        var executed = new HashSet<int>();
        var (outOfOrder, unexplained, latest, byField) = (0, 0, 0, 0);
        var findings = new List<string>();
        foreach (var change in changes)
        {
            image.Apply(change);
            history.Record(change, image);
            if (ChangeAttribution.IsFieldArea(change.Area))
            {
                if (ChangeAttribution.IsFields(fieldSettings, change))
                {
                    byField++;
                }
                else
                {
                    unexplained++;
                    findings.Add($"{Describe(change)}: not what the field set");
                }

                continue;
            }

            if (ChangeAttribution.WriteOf(writes, change, image) is not { } write)
            {
                unexplained++;
                findings.Add($"{Describe(change)}: no panel write explains it");
                continue;
            }

            if (write.Number < latest)
            {
                outOfOrder++;
                findings.Add($"write {write.Number} ({write.Address}) executed after write {latest}");
            }

            executed.Add(write.Number);
            latest = Math.Max(latest, write.Number);
        }

        var wrong = shown.Where(v => !history.WasHeld(v.Address, v.Value, v.From, v.Until)).ToList();
        findings.AddRange(wrong.Select(v => $"{v.Address} shown as good 16#{Convert.ToHexString(v.Value.AsSpan())}, which it did not hold then"));

        var confirmed = writes.Where(w => IsConfirmed(w.Outcome)).ToList();
        var notConfirmed = writes.Where(w => !IsConfirmed(w.Outcome)).ToList();
        var unseen = confirmed.Where(w => !executed.Contains(w.Number)).ToList();
        var alreadyHeld = unseen.Where(w => history.HeldThroughout(w.Address, w.Value, w.Sent, w.Reported)).ToList();
        var falselyConfirmed = unseen.Except(alreadyHeld).ToList();
        findings.AddRange(falselyConfirmed.Select(w => $"write {w.Number} {w.Address} := 16#{Convert.ToHexString(w.Value.AsSpan())} reported {Describe(w.Outcome)}, not executed as sent"));
        return new SoakJudgement(
            ValuesShownGood: shown.Count,
            WrongValuesShownGood: wrong.Count,
            WritesSent: writes.Count,
            WritesConfirmed: confirmed.Count,
            ConfirmedByReadBack: confirmed.Count(w => w.Outcome is WriteOutcome.ConfirmedByReadBack),
            ConfirmedAlreadyHeld: alreadyHeld.Count,
            FalseConfirmations: falselyConfirmed.Count,
            WritesOutOfOrder: outOfOrder,
            WritesNotConfirmed: notConfirmed.GroupBy(w => Describe(w.Outcome)).ToImmutableSortedDictionary(g => g.Key, g => g.Count()),
            NotConfirmedButExecuted: notConfirmed.Count(w => executed.Contains(w.Number)),
            FalseNotApplied: notConfirmed.Count(w => (w.Outcome is WriteOutcome.NotApplied or WriteOutcome.Failed) && executed.Contains(w.Number)),
            ExecutedNeverSent: unexplained,
            FieldChanges: byField,
            ShownGoodByItem: Count(shown.Select(v => v.Address)),
            ConfirmedByItem: Count(confirmed.Select(w => w.Address)),
            Findings: [.. findings.Take(FindingsKept)]);
    }

    /// <summary>The panel says the PLC holds the value: from the reply, or from a read-back after the reply was lost.</summary>
    public static bool IsConfirmed(WriteOutcome outcome) => outcome is WriteOutcome.Confirmed or WriteOutcome.ConfirmedByReadBack;

    /// <summary>What the panel reported, in the words of the figures.</summary>
    public static string Describe(WriteOutcome outcome) => outcome switch
    {
        WriteOutcome.Confirmed => "confirmed",
        WriteOutcome.ConfirmedByReadBack => "confirmed by read-back",
        WriteOutcome.NotApplied => "not applied",
        WriteOutcome.Unknown => "unknown",
        WriteOutcome.ReadBackMismatch => "read back differently",
        WriteOutcome.Failed failed => failed.Kind switch
        {
            WriteFailureKind.InvalidRequest => "invalid request",
            WriteFailureKind.RefusedByPlc => "refused by the PLC",
            WriteFailureKind.LinkFailure => "port failure (not sent)",
            WriteFailureKind.UnexpectedReply => "unexpected reply",
            WriteFailureKind.EngineStopped => "engine stopped (not sent)",
            WriteFailureKind.NotRecorded => "not put on record (not sent)",
        },
        _ => throw new ArgumentOutOfRangeException(nameof(outcome), outcome, "a write outcome the soak does not know"),
    };

    private static string Describe(MemoryChange change) =>
        $"{change.Area} bytes {change.First}-{change.Last} changed {Convert.ToHexString(change.Before.AsSpan())} -> {Convert.ToHexString(change.After.AsSpan())}";

    private static ImmutableSortedDictionary<string, int> Count(IEnumerable<Core.Addressing.PlcAddress> addresses) =>
        addresses.GroupBy(a => a.ToString()).ToImmutableSortedDictionary(g => g.Key, g => g.Count(), StringComparer.Ordinal);
}
