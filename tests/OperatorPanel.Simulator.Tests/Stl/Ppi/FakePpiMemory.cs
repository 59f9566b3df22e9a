using OperatorPanel.Core.Ppi.S7;
using OperatorPanel.Simulator.Stl.Ppi;

namespace OperatorPanel.Simulator.Tests.Stl.Ppi;

/// <summary>Byte arrays per area, read and written as a CPU 224 would have them; counts what was done.</summary>
internal sealed class FakePpiMemory : IPpiMemory
{
    public Dictionary<S7Area, byte[]> Areas { get; } = new()
    {
        [S7Area.I] = new byte[16],
        [S7Area.Q] = new byte[16],
        [S7Area.M] = new byte[32],
        [S7Area.V] = new byte[8192],
    };

    public List<S7Function> Controls { get; } = [];

    public int Reads { get; private set; }

    public S7ItemResult Read(S7Item item)
    {
        Reads++;
        var bytes = Areas[item.Area];
        return item.ByteOffset + item.DataLength > bytes.Length
            ? S7ItemResult.Failed(S7ReturnCode.AddressOutOfRange)
            : S7ItemResult.Of(S7DataSize.Bits, bytes.AsSpan(item.ByteOffset, item.DataLength));
    }

    public S7ReturnCode Write(S7WriteItem item)
    {
        item.Data.AsSpan().CopyTo(Areas[item.Item.Area].AsSpan(item.Item.ByteOffset));
        return S7ReturnCode.Success;
    }

    public bool Control(S7Function function)
    {
        Controls.Add(function);
        return true;
    }
}
