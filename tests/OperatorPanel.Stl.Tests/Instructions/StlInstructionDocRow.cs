using System.Globalization;
using OperatorPanel.Stl.Instructions;

namespace OperatorPanel.Stl.Tests.Instructions;

/// <summary>One table row of docs/stl-instructions.md as the code table says it should read, cell by cell.</summary>
internal static class StlInstructionDocRow
{
    public const string Header = "| Mnemonic | Operands (name TYPE access: kinds) | CPUs | SMB1 | ENO = 0 | Written in | Source |";

    public static string[] Cells(StlInstructionSpec spec) =>
    [
        $"`{spec.Mnemonic}`",
        spec.Operands.IsEmpty ? "-" : string.Join("; ", spec.Operands.Select(Operand)) + (spec.TakesParameters ? "; parameters" : string.Empty),
        spec.Firmware == StlFirmware.All ? "all" : "firmware 2.0+",
        StatusBits(spec.StatusBits),
        spec.EnoErrors.Length == 0 ? "-" : spec.EnoErrors,
        Placement(spec.Placement),
        spec.Source,
    ];

    public static string Format(StlInstructionSpec spec) => "| " + string.Join(" | ", Cells(spec)) + " |";

    private static string Operand(StlOperandSpec o)
    {
        var access = o.Access switch
        {
            StlAccess.Read => "r",
            StlAccess.Write => "w",
            StlAccess.ReadWrite => "rw",
            _ => throw new ArgumentOutOfRangeException(nameof(o), o.Access, null),
        };
        var range = o.Min is { } min && o.Max is { } max ? string.Create(CultureInfo.InvariantCulture, $" {min}..{max}") : string.Empty;
        var extent = o.Extent switch
        {
            StlExtent.One => o.Length > 1 ? string.Create(CultureInfo.InvariantCulture, $" x{o.Length}") : string.Empty,
            StlExtent.Count => " xN",
            StlExtent.HalfCount => " x(N+1)/2",
            StlExtent.AbsoluteCount => " x|N|",
            _ => throw new ArgumentOutOfRangeException(nameof(o), o.Extent, null),
        };
        return $"{o.Name} {o.Type.ToString().ToUpperInvariant()} {access}{extent}: {StlOperandKindsText.Describe(o)}{range}";
    }

    private static string StatusBits(StlStatusBits bits)
    {
        var set = Enumerable.Range(0, 8).Where(b => ((int)bits & (1 << b)) != 0).Select(b => string.Create(CultureInfo.InvariantCulture, $"SM1.{b}"));
        return bits == StlStatusBits.None ? "-" : string.Join(" ", set);
    }

    private static string Placement(StlPlacement placement)
    {
        if (placement == StlPlacement.None)
        {
            return "never (Micro/WIN adds it)";
        }

        return placement == StlPlacement.Anywhere ? "any"
            : string.Join(", ", new[] { (StlPlacement.Main, "OB1"), (StlPlacement.Subroutine, "SBR"), (StlPlacement.InterruptRoutine, "INT") }
                .Where(p => placement.HasFlag(p.Item1)).Select(p => p.Item2));
    }
}
