using System.Runtime.CompilerServices;
using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Merge.UserPrograms;

/// <summary>User programs for the merge tests: the exported files beside this source, and small OB1-only programs with known line numbers.</summary>
internal static class UserProgram
{
    /// <summary>Instruction lines of <see cref="Ob1"/> start at this line.</summary>
    public const int FirstInstructionLine = 4;

    public static HandlerOptions Cpu224 => new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 };

    public static HandlerOptions Cpu226 => new() { Protocol = 2, Cpu = CpuProfiles.For(CpuModel.Cpu226), Station = 2 };

    /// <summary>A file beside this source file (the folder of UserProgram.cs, whoever calls).</summary>
    public static string Read(string name) => File.ReadAllText(Path.Combine(Folder(), name));

    /// <summary>
    /// OB1 with one network of the given instruction lines, then an interrupt routine for each name an ATCH of them
    /// attaches (INT0, INT1 ... in order: Micro/WIN refuses an ATCH to a routine the file does not hold); CRLF line ends.
    /// </summary>
    public static string Ob1(params string[] instructions) => WithBlocks(instructions, AttachedRoutines(instructions));

    public static string WithBlocks(string[] instructions, string[] blocks) =>
        string.Concat(Header.Concat(instructions).Append("END_ORGANIZATION_BLOCK").Concat(blocks).Select(l => l + "\r\n"));

    private static string[] AttachedRoutines(string[] instructions) =>
    [
        .. instructions.Where(i => i.StartsWith("ATCH", StringComparison.Ordinal))
            .Select(i => i[4..].Split(',')[0].Trim()).Distinct()
            .SelectMany((name, n) => (string[])[$"INTERRUPT_BLOCK {(name.StartsWith("INT", StringComparison.Ordinal) && name.Length <= 6 ? "INT_" + name[3..] : name)}:INT{(name.StartsWith("INT", StringComparison.Ordinal) && name.Length <= 6 ? name[3..] : n)}", "BEGIN", "Network 1", "END_INTERRUPT_BLOCK"]),
    ];

    private static string Folder([CallerFilePath] string self = "") => Path.GetDirectoryName(self)!;

    private static readonly string[] Header = ["ORGANIZATION_BLOCK MAIN:OB1", "BEGIN", "Network 1 // test"];
}
