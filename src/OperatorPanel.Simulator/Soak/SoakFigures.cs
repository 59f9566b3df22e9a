using System.Collections.Immutable;
using System.Globalization;

namespace OperatorPanel.Simulator.Soak;

/// <summary>
/// What a soak run measured. <see cref="WrongValuesShownGood"/>, <see cref="FalseConfirmations"/> and
/// <see cref="WritesOutOfOrder"/> must be 0; the rest describe the line and how the panel coped with it.
/// </summary>
public sealed record SoakFigures
{
    public required string Faults { get; init; }

    public required int Seed { get; init; }

    /// <summary>The addresses watched (and written in Q, M and V), as <see cref="SoakRegion"/> prints them.</summary>
    public required string Region { get; init; }

    public required TimeSpan Elapsed { get; init; }

    /// <summary>Requests the link sent, retries included.</summary>
    public required long Exchanges { get; init; }

    public required long Retries { get; init; }

    public required long Timeouts { get; init; }

    public required long CorruptReplies { get; init; }

    public required long NegativeReplies { get; init; }

    public required int ValuesShownGood { get; init; }

    /// <summary>Good values the PLC did not hold at that address at any moment of the step that showed them.</summary>
    public required int WrongValuesShownGood { get; init; }

    public required int WritesSent { get; init; }

    public required int WritesConfirmed { get; init; }

    /// <summary>Of <see cref="WritesConfirmed"/>, those confirmed by reading back after the reply was lost.</summary>
    public required int ConfirmedByReadBack { get; init; }

    /// <summary>
    /// Of <see cref="WritesConfirmed"/>, those with no change to see because the address already held the value from
    /// the write's start to its report (a byte or bit value recurs); the PLC holds what the panel says.
    /// </summary>
    public int ConfirmedAlreadyHeld { get; init; }

    /// <summary>Confirmed writes (from the reply or by read-back) the PLC did not execute exactly (that address, those bytes, nothing more).</summary>
    public required int FalseConfirmations { get; init; }

    /// <summary>Executed panel writes that came after a later one of the panel's writes had been executed.</summary>
    public required int WritesOutOfOrder { get; init; }

    /// <summary>Writes not confirmed, by what the panel reported.</summary>
    public required ImmutableSortedDictionary<string, int> WritesNotConfirmed { get; init; }

    /// <summary>Writes not reported confirmed that the PLC did execute exactly.</summary>
    public required int NotConfirmedButExecuted { get; init; }

    /// <summary>Writes reported as certainly not written (not applied, failed) that the PLC did execute.</summary>
    public required int FalseNotApplied { get; init; }

    /// <summary>
    /// Memory changes nothing explains: in Q, M or V no panel write (the PLC acted on a corrupted request), in I or SM
    /// not the field's latest setting.
    /// </summary>
    public required int ExecutedNeverSent { get; init; }

    /// <summary>Changes of I and SM the observer saw that the field made (<see cref="SoakField"/>): what READ LIST had to carry besides the writes.</summary>
    public int FieldChanges { get; init; }

    /// <summary>Good values shown per address: the workload reached it.</summary>
    public ImmutableSortedDictionary<string, int> ShownGoodByItem { get; init; } = ImmutableSortedDictionary<string, int>.Empty;

    /// <summary>Writes confirmed per address.</summary>
    public ImmutableSortedDictionary<string, int> ConfirmedByItem { get; init; } = ImmutableSortedDictionary<string, int>.Empty;

    /// <summary>The first findings in words (see <see cref="SoakJudgement.Findings"/>).</summary>
    public required ImmutableArray<string> Findings { get; init; }

    public required long CharactersOnLine { get; init; }

    public required long BitsFlipped { get; init; }

    public required long CharactersDropped { get; init; }

    public required long FramesDropped { get; init; }

    /// <summary>Lines run side by side (own pty pairs, PLC and seed each), counted together.</summary>
    public int Lines { get; init; } = 1;

    /// <summary>Lines whose handler answered one of the soak's IDENTIFY attempts (the list reader also asks IDENTIFY itself before its first DEFINE LIST).</summary>
    public int LinesIdentified { get; init; }

    public bool ZerosHold => WrongValuesShownGood == 0 && FalseConfirmations == 0 && WritesOutOfOrder == 0;

    /// <summary>The figures of lines run side by side as one run: counts added, the longest elapsed time, the first seed.</summary>
    public static SoakFigures Combine(IReadOnlyList<SoakFigures> lines)
    {
        ArgumentNullException.ThrowIfNull(lines);
        return lines[0] with
        {
            Lines = lines.Sum(f => f.Lines),
            Elapsed = lines.Max(f => f.Elapsed),
            Exchanges = lines.Sum(f => f.Exchanges),
            Retries = lines.Sum(f => f.Retries),
            Timeouts = lines.Sum(f => f.Timeouts),
            CorruptReplies = lines.Sum(f => f.CorruptReplies),
            NegativeReplies = lines.Sum(f => f.NegativeReplies),
            ValuesShownGood = lines.Sum(f => f.ValuesShownGood),
            WrongValuesShownGood = lines.Sum(f => f.WrongValuesShownGood),
            WritesSent = lines.Sum(f => f.WritesSent),
            WritesConfirmed = lines.Sum(f => f.WritesConfirmed),
            ConfirmedByReadBack = lines.Sum(f => f.ConfirmedByReadBack),
            ConfirmedAlreadyHeld = lines.Sum(f => f.ConfirmedAlreadyHeld),
            FalseConfirmations = lines.Sum(f => f.FalseConfirmations),
            WritesOutOfOrder = lines.Sum(f => f.WritesOutOfOrder),
            WritesNotConfirmed = lines.SelectMany(f => f.WritesNotConfirmed).GroupBy(p => p.Key)
                .ToImmutableSortedDictionary(g => g.Key, g => g.Sum(p => p.Value)),
            NotConfirmedButExecuted = lines.Sum(f => f.NotConfirmedButExecuted),
            FalseNotApplied = lines.Sum(f => f.FalseNotApplied),
            ExecutedNeverSent = lines.Sum(f => f.ExecutedNeverSent),
            FieldChanges = lines.Sum(f => f.FieldChanges),
            ShownGoodByItem = Sum(lines.Select(f => f.ShownGoodByItem)),
            ConfirmedByItem = Sum(lines.Select(f => f.ConfirmedByItem)),
            Findings = [.. lines.SelectMany(f => f.Findings).Take(10)],
            CharactersOnLine = lines.Sum(f => f.CharactersOnLine),
            BitsFlipped = lines.Sum(f => f.BitsFlipped),
            CharactersDropped = lines.Sum(f => f.CharactersDropped),
            FramesDropped = lines.Sum(f => f.FramesDropped),
            LinesIdentified = lines.Sum(f => f.LinesIdentified),
        };
    }

    public IEnumerable<string> Text()
    {
        var c = CultureInfo.InvariantCulture;
        var lines = Lines == 1 ? "" : $", {Lines} lines side by side (seeds from {Seed})";
        yield return string.Create(c, $"soak {Faults}, seed {Seed}, {Elapsed.TotalSeconds:F0} s{lines}");
        yield return $"  region: {Region}";
        yield return string.Create(c, $"  line: {CharactersOnLine} characters, {BitsFlipped} bits flipped, {CharactersDropped} characters dropped, {FramesDropped} frames dropped");
        yield return string.Create(c, $"  exchanges {Exchanges}, retries {Retries}, timeouts {Timeouts}, corrupt replies {CorruptReplies}, error replies {NegativeReplies}");
        yield return string.Create(c, $"  handler identified on {LinesIdentified} of {Lines} line(s) before the list reader asked itself");
        yield return string.Create(c, $"  values shown as good {ValuesShownGood}, wrong values shown as good {WrongValuesShownGood} (must be 0)");
        yield return "  good values per address: " + PerItem(ShownGoodByItem, all: true);
        yield return string.Create(c, $"  writes {WritesSent}, confirmed {WritesConfirmed} ({ConfirmedByReadBack} by read-back, {ConfirmedAlreadyHeld} with the value already there), false confirmations {FalseConfirmations} (must be 0), executed out of order {WritesOutOfOrder} (must be 0)");
        yield return "  confirmed writes per address: " + PerItem(ConfirmedByItem, all: false);
        var notConfirmed = WritesNotConfirmed.Count == 0 ? "none" : string.Join(", ", WritesNotConfirmed.Select(p => $"{p.Key} {p.Value}"));
        yield return string.Create(c, $"  writes not confirmed: {notConfirmed}; of them executed by the PLC {NotConfirmedButExecuted}, reported as certainly not written {FalseNotApplied}");
        yield return string.Create(c, $"  I and SM changes the field made, seen in the PLC: {FieldChanges}");
        yield return string.Create(c, $"  PLC memory changes nothing explains (Q, M, V: no panel write, the PLC acted on a corrupted request; I, SM: not the field): {ExecutedNeverSent}");
        foreach (var finding in Findings)
        {
            yield return "  finding: " + finding;
        }

        yield return ZerosHold ? "  result: the zeros hold" : "  result: FAILED, a must-be-0 figure is not 0";
    }

    private static ImmutableSortedDictionary<string, int> Sum(IEnumerable<ImmutableSortedDictionary<string, int>> counts) =>
        counts.SelectMany(d => d).GroupBy(p => p.Key).ToImmutableSortedDictionary(g => g.Key, g => g.Sum(p => p.Value), StringComparer.Ordinal);

    /// <summary>"VD1000 12, VD1004 9, ..." in the region's order; with <paramref name="all"/> the addresses with none too.</summary>
    private string PerItem(ImmutableSortedDictionary<string, int> counts, bool all)
    {
        var items = Region.Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(a => (Address: a, Count: counts.GetValueOrDefault(a)))
            .Where(p => all || p.Count > 0)
            .Select(p => string.Create(CultureInfo.InvariantCulture, $"{p.Address} {p.Count}"))
            .ToList();
        return items.Count == 0 ? "none" : string.Join(", ", items);
    }
}
