using System.Collections.Immutable;

namespace OperatorPanel.Core.Ppi.S7;

/// <summary>One item of a read answer: its return code and, on success, its bytes.</summary>
public sealed record S7ItemResult(S7ReturnCode Code, S7DataSize DataSize, ImmutableArray<byte> Data)
{
    public bool Succeeded => Code == S7ReturnCode.Success;

    public static S7ItemResult Failed(S7ReturnCode code) => new(code, S7DataSize.None, []);

    public static S7ItemResult Of(S7DataSize size, ReadOnlySpan<byte> data) => new(S7ReturnCode.Success, size, [.. data]);
}
