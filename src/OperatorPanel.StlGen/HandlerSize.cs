using System.Globalization;
using OperatorPanel.Core.Cpu;

namespace OperatorPanel.StlGen;

/// <summary>
/// How much program memory the handler takes, as far as can be known without Micro/WIN: its instructions and networks
/// counted, and a range of bytes estimated from them, beside the CPU's program memory. Siemens publishes no byte size
/// per S7-200 instruction (docs/sources/s7200-facts.md section 14), so the bytes are an estimate and Micro/WIN's
/// compile is the final word. The sentences here are the one wording <c>opanel generate</c>, the technician notes and
/// Generate PLC code share.
/// </summary>
/// <param name="Instructions">The handler's STL instructions, all blocks.</param>
/// <param name="Networks">The networks of all its blocks (OB1's call included).</param>
/// <param name="Cpu">The CPU it is generated for.</param>
/// <param name="CompactInstructions">A full protocol 3 handler: the compact one's instructions for the same options, the
/// first way out the warning offers; null for a compact or a protocol 2 handler.</param>
public sealed record HandlerSize(int Instructions, int Networks, CpuProfile Cpu, int? CompactInstructions = null)
{
    /// <summary>The low end of the estimate: an operation and one short operand.</summary>
    public const int LowBytesPerInstruction = 4;

    /// <summary>The high end of the estimate: an operation and two or three operands with offsets.</summary>
    public const int HighBytesPerInstruction = 7;

    /// <summary>Siemens' Modbus RTU slave library (MBUS_INIT, MBUS_SLAVE): "1857 bytes of program space" (ML801761 p. 363).</summary>
    public const int ModbusSlaveProgramBytes = 1857;

    /// <summary>The same library's "779-byte block of V memory".</summary>
    public const int ModbusSlaveVBytes = 779;

    public int LowBytes => Instructions * LowBytesPerInstruction;

    public int HighBytes => Instructions * HighBytesPerInstruction;

    /// <summary>The CPU's program memory with run mode edit, the conservative of the manual's two figures.</summary>
    public int ProgramMemoryBytes => Cpu.ProgramBytes;

    /// <summary>The upper estimate takes more than half the CPU's program memory: the user's own program may not fit beside it.</summary>
    public bool ExceedsHalfOfProgramMemory => HighBytes * 2 > ProgramMemoryBytes;

    /// <summary>"4764-8337 bytes (4-7 bytes an instruction)".</summary>
    public string EstimateText => Text($"{LowBytes}-{HighBytes} bytes ({LowBytesPerInstruction}-{HighBytesPerInstruction} bytes an instruction)");

    /// <summary>The basis of the estimate, in one sentence.</summary>
    public static string BasisText =>
        "Siemens publishes no byte size per S7-200 instruction, so this is an estimate; Micro/WIN's compile gives the real size";

    /// <summary>"8192 bytes on the CPU 224 (with run mode edit; 12288 without)".</summary>
    public string ProgramMemoryText => Cpu.ProgramBytesWithoutRunModeEdit == Cpu.ProgramBytes
        ? Text($"{ProgramMemoryBytes} bytes on the {Cpu.DisplayName}")
        : Text($"{ProgramMemoryBytes} bytes on the {Cpu.DisplayName} (with run mode edit; {Cpu.ProgramBytesWithoutRunModeEdit} without)");

    /// <summary>What a PLC programmer compares the handler with.</summary>
    public static string ModbusComparisonText => Text(
        $"Siemens' Modbus RTU slave library takes {ModbusSlaveProgramBytes} bytes of program and a {ModbusSlaveVBytes}-byte V block (S7-200 System Manual, Modbus Protocol Library)");

    /// <summary>
    /// The warning when <see cref="ExceedsHalfOfProgramMemory"/>, else null: <see cref="WarningVerdict"/> (which CPU,
    /// the figures), then <see cref="WarningAdvice"/> (what to do), as one text.
    /// </summary>
    public string? Warning => WarningVerdict is { } verdict ? $"{verdict}. {WarningAdvice}" : null;

    /// <summary>
    /// Which CPU and the figures; where even the lower figure is more than the whole program memory it says the handler
    /// does not fit. Null when the size is fine.
    /// </summary>
    public string? WarningVerdict
    {
        get
        {
            if (!ExceedsHalfOfProgramMemory)
            {
                return null;
            }

            var figures = Text($"its {Instructions} instructions take an estimated {LowBytes}-{HighBytes} bytes");
            var memory = Text($"the CPU's {ProgramMemoryBytes} bytes of program memory (with run mode edit)");
            return LowBytes > ProgramMemoryBytes
                ? $"the handler does not fit the {Cpu.DisplayName}: {figures}, more than {memory} even at the lower figure"
                : $"the handler may leave too little room on the {Cpu.DisplayName}: {figures}, and the upper figure is more than half of {memory}";
        }
    }

    /// <summary>The first thing to do about the warning, before <see cref="WarningWays"/>.</summary>
    public const string CompileFirstText = "Compile it with your program in Micro/WIN to see the real size; where they do not fit together";

    /// <summary>
    /// What to do: compile in Micro/WIN (<see cref="CompileFirstText"/>), then <see cref="WarningWays"/>. Null when the
    /// size is fine.
    /// </summary>
    public string? WarningAdvice => WarningWays is { } ways ? $"{CompileFirstText}, {ways}" : null;

    /// <summary>
    /// The ways out: the compact handler where this is a full one, a CPU with more program memory where there is one, or
    /// PPI. Null when the size is fine.
    /// </summary>
    public string? WarningWays
    {
        get
        {
            if (!ExceedsHalfOfProgramMemory)
            {
                return null;
            }

            var larger = CpuProfiles.All.Where(p => p.Revision == CpuRevision.Current && p.ProgramBytes > ProgramMemoryBytes)
                .Select(p => Text($"{p.Name} {p.ProgramBytes} bytes")).ToList();
            var largerCpu = larger.Count == 0 ? string.Empty : $"use a CPU with more program memory ({string.Join(", ", larger)}), or ";
            var compact = CompactInstructions is { } n
                ? Text($"use the compact handler (the wizard's \"Compact handler\", \"compact\": true in the project or --compact: IDENTIFY, READ, WRITE, WRITE BITS; {n} instructions, estimated {n * LowBytesPerInstruction}-{n * HighBytesPerInstruction} bytes), ")
                : string.Empty;
            return compact + largerCpu + "reach this PLC over PPI (\"protocol\": \"ppi\" in the project), which needs no program in the PLC";
        }
    }

    private static string Text(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
