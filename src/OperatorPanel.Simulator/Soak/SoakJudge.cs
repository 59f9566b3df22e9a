using System.Collections.Immutable;
using OperatorPanel.Core.Writes;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// Holds the panel's claims (values shown as good, writes confirmed) against the PLC's executed writes as the
/// <see cref="ExecutedWriteObserver"/> saw them. The soak writes double words into a region of V, each value once
/// in the whole run, so a change of the region names the write it executed: its value is in exactly one write.
/// </summary>
public sealed class SoakJudge(SoakRegion region, ReadOnlyMemory<byte> initial)
{
    /// <summary>Findings kept for the report: enough to see what went wrong, not a log.</summary>
    private const int FindingsKept = 10;

    public SoakJudgement Judge(IReadOnlyList<SoakWrite> writes, IReadOnlyList<ShownValue> shown, IReadOnlyList<MemoryChange> changes)
    {
        ArgumentNullException.ThrowIfNull(writes);
        ArgumentNullException.ThrowIfNull(shown);
        ArgumentNullException.ThrowIfNull(changes);
        var byValue = writes.ToDictionary(w => w.Value);
        var timelines = region.Slots.ToDictionary(s => s, s => new List<(long At, uint Value)> { (long.MinValue, region.Read(initial.Span, s)) });
        var bytes = initial.ToArray();
        var executed = new HashSet<int>();
        var (outOfOrder, neverSent, latest) = (0, 0, 0);
        var findings = new List<string>();
        foreach (var change in changes)
        {
            var inside = region.Apply(change, bytes);
            var touched = region.Slots.Where(s => s <= change.Last && s + 3 >= change.First).ToList();
            foreach (var slot in touched)
            {
                timelines[slot].Add((change.Timestamp, region.Read(bytes, slot)));
            }

            if (inside && touched is [var only] && byValue.TryGetValue(region.Read(bytes, only), out var write) && write.Offset == only
                && change.First >= only && change.Last <= only + 3)
            {
                executed.Add(write.Number);
                if (write.Number < latest)
                {
                    outOfOrder++;
                    findings.Add($"write {write.Number} (VD{write.Offset}) executed after write {latest}");
                }

                latest = Math.Max(latest, write.Number);
            }
            else
            {
                neverSent++;
                findings.Add($"{change.Area} bytes {change.First}-{change.Last} changed {Convert.ToHexString(change.Before.AsSpan())} -> "
                    + $"{Convert.ToHexString(change.After.AsSpan())}: no panel write explains it");
            }
        }

        var wrong = shown.Where(v => !WasHeld(timelines[v.Offset], v)).ToList();
        findings.AddRange(wrong.Select(v => $"VD{v.Offset} shown as good 16#{v.Value:X8}, which it did not hold then"));

        var confirmed = writes.Where(w => IsConfirmed(w.Outcome)).ToList();
        var notConfirmed = writes.Where(w => !IsConfirmed(w.Outcome)).ToList();
        var falselyConfirmed = confirmed.Where(w => !executed.Contains(w.Number)).ToList();
        findings.AddRange(falselyConfirmed.Select(w => $"write {w.Number} VD{w.Offset} := 16#{w.Value:X8} reported {Describe(w.Outcome)}, not executed as sent"));
        return new SoakJudgement(
            ValuesShownGood: shown.Count,
            WrongValuesShownGood: wrong.Count,
            WritesSent: writes.Count,
            WritesConfirmed: confirmed.Count,
            ConfirmedByReadBack: confirmed.Count(w => w.Outcome is WriteOutcome.ConfirmedByReadBack),
            FalseConfirmations: falselyConfirmed.Count,
            WritesOutOfOrder: outOfOrder,
            WritesNotConfirmed: notConfirmed.GroupBy(w => Describe(w.Outcome)).ToImmutableSortedDictionary(g => g.Key, g => g.Count()),
            NotConfirmedButExecuted: notConfirmed.Count(w => executed.Contains(w.Number)),
            FalseNotApplied: notConfirmed.Count(w => (w.Outcome is WriteOutcome.NotApplied or WriteOutcome.Failed) && executed.Contains(w.Number)),
            ExecutedNeverSent: neverSent,
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

    /// <summary>True when the slot held the value for some moment between the shown value's bounds.</summary>
    private static bool WasHeld(List<(long At, uint Value)> timeline, ShownValue shown)
    {
        for (var i = 0; i < timeline.Count; i++)
        {
            var ends = i + 1 < timeline.Count ? timeline[i + 1].At : long.MaxValue;
            if (timeline[i].Value == shown.Value && timeline[i].At <= shown.Until && ends > shown.From)
            {
                return true;
            }
        }

        return false;
    }
}
