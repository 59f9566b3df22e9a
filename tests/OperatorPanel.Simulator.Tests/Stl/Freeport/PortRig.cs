using System.Text;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Simulator.Reference;
using OperatorPanel.Simulator.Stl;
using OperatorPanel.Simulator.Stl.Freeport;

namespace OperatorPanel.Simulator.Tests.Stl.Freeport;

/// <summary>One CPU's memory and port, its receive set-up in SM, and the events the port raised.</summary>
internal sealed class PortRig
{
    public const int Buffer = 100;

    private readonly int _smOffset;

    public PortRig(CpuModel model = CpuModel.Cpu224, int port = 0, LineSettings? pc = null)
    {
        Memory = new PlcMemory(CpuProfiles.For(model));
        Port = new FreeportPort(port, Memory, CpuProfiles.For(model), pc ?? LineSettings.Default);
        _smOffset = port == 0 ? 0 : 100;
    }

    public PlcMemory Memory { get; }

    public FreeportPort Port { get; }

    public List<StlEvent> Events { get; } = [];

    public byte Status => Memory.SM[86 + _smOffset];

    public byte[] Received => Memory.V.AsSpan(Buffer + 1, Memory.V[Buffer]).ToArray();

    public string ReceivedText => Encoding.ASCII.GetString(Received);

    /// <summary>9600 8N1 Freeport (16#09), en+sc+ec (16#E0), '&lt;' ... '&gt;', 255 characters.</summary>
    public PortRig Setup(byte mode = 0x09, byte control = 0xE0, byte start = 0x3C, byte end = 0x3E, int idleMs = 0, int timerMs = 0, byte max = 255)
    {
        var sm = Memory.SM;
        sm[30 + _smOffset] = mode;
        sm[87 + _smOffset] = control;
        sm[88 + _smOffset] = start;
        sm[89 + _smOffset] = end;
        sm[90 + _smOffset] = (byte)(idleMs >> 8);
        sm[91 + _smOffset] = (byte)idleMs;
        sm[92 + _smOffset] = (byte)(timerMs >> 8);
        sm[93 + _smOffset] = (byte)timerMs;
        sm[94 + _smOffset] = max;
        return this;
    }

    public void Deliver(string text, TimeSpan at) => Port.Deliver(Encoding.ASCII.GetBytes(text), at);

    public void RunTo(TimeSpan at) => Port.AdvanceTo(at, Events);

    /// <summary>Advances from change to change until the port has nothing left to do.</summary>
    public void RunToEnd()
    {
        for (var guard = 0; guard < 100_000 && Port.NextChange is { } next; guard++)
        {
            RunTo(next);
        }
    }

    public void LoadTransmitBuffer(string text)
    {
        Memory.V[Buffer] = (byte)text.Length;
        Encoding.ASCII.GetBytes(text).CopyTo(Memory.V, Buffer + 1);
    }

    public static TimeSpan Ms(double milliseconds) => TimeSpan.FromTicks((long)Math.Round(milliseconds * TimeSpan.TicksPerMillisecond));

    /// <summary>The time <paramref name="characters"/> characters take at 9600 8N1 (10 bits each).</summary>
    public static TimeSpan Chars(int characters) => LineSettings.Default.Bits(10L * characters);
}
