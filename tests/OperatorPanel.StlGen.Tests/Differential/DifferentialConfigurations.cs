using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;
using OperatorPanel.StlGen.Options;

namespace OperatorPanel.StlGen.Tests.Differential;

/// <summary>
/// The configurations the differential tests run: every CPU model and revision, both ports where present, 1200 to
/// 115200 baud (115200 only on Current CPUs) with 8N1, 8E1 and 7O1, stations 1, 17 and 126, buffers at the default
/// (top of V), VB0, VB100 and an odd address in the middle, write masks all / none / V only, reply delays 1 and
/// 255 ms, and the inter-character timeout on and off.
/// </summary>
internal static class DifferentialConfigurations
{
    public static IReadOnlyList<HandlerOptions> All { get; } = Build();

    public static string Describe(HandlerOptions o) =>
        $"{o.Cpu.DisplayName} port {o.Port} {o.BaudRate} {o.DataBits}{o.Parity.ToString()[0]}1 station {o.Station} buffer VB{o.EffectiveBufferStart} mask 16#{o.WriteMask:X2} delay {o.ReplyDelayMs} ms char timeout {o.CharTimeoutMs} ms";

    private static List<HandlerOptions> Build()
    {
        var list = new List<HandlerOptions>();
        var i = 0;
        foreach (var cpu in CpuProfiles.All)
        {
            for (var port = 0; port < cpu.CommunicationPorts; port++)
            {
                // Two settings per CPU and port, rotating through the lists so every value meets several CPUs.
                for (var k = 0; k < 2; k++, i++)
                {
                    list.Add(new HandlerOptions
                    {
                        Protocol = 2,
                        Cpu = cpu,
                        Port = port,
                        BaudRate = Baud(cpu, i),
                        Parity = (i % 3) switch { 0 => Parity.None, 1 => Parity.Even, _ => Parity.Odd },
                        DataBits = i % 3 == 2 ? 7 : 8,
                        Station = (i % 3) switch { 0 => 1, 1 => 17, _ => 126 },
                        BufferStart = (i % 4) switch { 0 => null, 1 => 0, 2 => 100, _ => ((HandlerDefaults.VBytes(cpu) / 2) | 1) },
                        WriteMask = (i % 5) switch { 0 => 0, 1 => 0x10, _ => HandlerDefaults.WriteMask },
                        ReplyDelayMs = i % 2 == 0 ? 1 : 255,
                        CharTimeoutMs = (i / 2) % 2 == 0 ? 0 : 100,
                    });
                }
            }
        }

        return list;
    }

    private static int Baud(CpuProfile cpu, int i) => (i % 4) switch
    {
        0 => 9600,
        1 => 19200,
        2 => 1200,
        _ => cpu.Revision == CpuRevision.Current ? 115200 : 9600,
    };
}
