using System.Runtime.CompilerServices;
using OperatorPanel.Core.Cpu;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Merge.UserPrograms;

/// <summary>User programs for the merge tests: the exported files beside this source, and small OB1-only programs with known line numbers.</summary>
internal static class UserProgram
{
    /// <summary>Instruction lines of <see cref="Ob1"/> start at this line.</summary>
    public const int FirstInstructionLine = 4;

    public static HandlerOptions Cpu224 => new() { Cpu = CpuProfiles.For(CpuModel.Cpu224), Station = 2 };

    public static HandlerOptions Cpu226 => new() { Cpu = CpuProfiles.For(CpuModel.Cpu226), Station = 2 };

    /// <summary>A file beside this source file (the folder of UserProgram.cs, whoever calls).</summary>
    public static string Read(string name) => File.ReadAllText(Path.Combine(Folder(), name));

    /// <summary>OB1 with one network of the given instruction lines, then the given extra blocks; CRLF line ends.</summary>
    public static string Ob1(params string[] instructions) => WithBlocks(instructions, []);

    public static string WithBlocks(string[] instructions, string[] blocks) =>
        string.Concat(Header.Concat(instructions).Append("END_ORGANIZATION_BLOCK").Concat(blocks).Select(l => l + "\r\n"));

    private static string Folder([CallerFilePath] string self = "") => Path.GetDirectoryName(self)!;

    private static readonly string[] Header = ["ORGANIZATION_BLOCK MAIN:OB1", "BEGIN", "Network 1 // test"];
}
