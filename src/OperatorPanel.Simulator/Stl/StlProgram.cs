using OperatorPanel.Core.Cpu;

namespace OperatorPanel.Simulator.Stl;

/// <summary>An .awl program checked and compiled for one CPU by <see cref="StlProgramLoader"/>, ready for <see cref="StlPlc"/>.</summary>
public sealed class StlProgram
{
    internal StlProgram(CpuProfile cpu, StlBlock[] blocks, int edgeCount)
    {
        Cpu = cpu;
        Blocks = blocks;
        EdgeCount = edgeCount;
    }

    public CpuProfile Cpu { get; }

    /// <summary>Number of executable instructions over all blocks.</summary>
    public int InstructionCount => Blocks.Sum(b => b.Ops.Length);

    public IEnumerable<string> BlockNames => Blocks.Select(b => b.Name);

    /// <summary>Block 0 is OB1.</summary>
    internal StlBlock[] Blocks { get; }

    internal int EdgeCount { get; }
}
