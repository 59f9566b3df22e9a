using System.Collections.Immutable;

namespace OperatorPanel.StlGen.Model;

/// <summary>Collects one network's instructions; <c>Op("MOVB", "16#09", "SMB30")</c> reads like the STL it makes.</summary>
internal sealed class NetworkBuilder(string title, params string[] comments)
{
    private readonly ImmutableArray<StlInstruction>.Builder _instructions = ImmutableArray.CreateBuilder<StlInstruction>();

    public NetworkBuilder Op(string mnemonic, params string[] operands)
    {
        _instructions.Add(StlInstruction.Of(mnemonic, operands));
        return this;
    }

    /// <summary>Several instructions in order, as <see cref="Op"/> would add them one by one.</summary>
    public NetworkBuilder Ops(IEnumerable<(string Mnemonic, string[] Operands)> instructions)
    {
        foreach (var (mnemonic, operands) in instructions)
        {
            Op(mnemonic, operands);
        }

        return this;
    }

    public StlNetwork Build() => new(title, [.. comments], _instructions.ToImmutable());
}
