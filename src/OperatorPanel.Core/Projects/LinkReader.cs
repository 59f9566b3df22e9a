using System.Globalization;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads a station's <c>link</c> object and checks it against what S7-200 Freeport can do (seed 002, Table C-11:
/// SMB30 holds the baud code, 7 or 8 data bits, parity none/even/odd; Freeport always sends one stop bit), or with
/// <c>"protocol": "ppi"</c> what PPI can do: 9600, 19200 or 187500 baud (seed 002 Tables A-2 to A-4), 8 data bits,
/// even parity, one stop bit (ML801761 p. 228), over the cable (docs/ppi.md).
/// </summary>
internal static class LinkReader
{
    public static SerialSettings? Read(JsonFields? fields, CpuProfile? cpu)
    {
        if (fields is null)
        {
            return null;
        }

        fields.ReportUnknown("port", "baud", "parity", "dataBits", "stopBits", "kind", "protocol");
        var port = TextRule.Port.Read(fields, "port");
        if (port is not null && string.IsNullOrWhiteSpace(port))
        {
            fields.Problem("port", "the serial port name is empty; write e.g. COM3 or /dev/ttyUSB0");
            port = null;
        }

        var protocol = fields.Word("protocol", LinkProtocol.Freeport);
        if (protocol == LinkProtocol.Ppi)
        {
            return ReadPpi(fields, port);
        }

        var baud = fields.Int("baud", 9600);
        if (baud is { } b && cpu is not null && cpu.FreeportBaudCode(b) is null)
        {
            var rates = string.Join(", ", cpu.FreeportBaudRates.Select(r => r.Baud).Order());
            fields.Problem("baud", string.Create(CultureInfo.InvariantCulture, $"{cpu.DisplayName} cannot run Freeport at {b} baud; use one of {rates}"));
            baud = null;
        }

        var parity = fields.Word("parity", Parity.None);
        var dataBits = fields.Int("dataBits", 8);
        if (dataBits is not (null or 7 or 8))
        {
            fields.Problem("dataBits", string.Create(CultureInfo.InvariantCulture, $"{dataBits} data bits: a Freeport character has 7 or 8 (SMB30 bit 5)"));
            dataBits = null;
        }

        var stopBits = fields.Int("stopBits", 1);
        if (stopBits is not (null or 1))
        {
            fields.Problem("stopBits", string.Create(CultureInfo.InvariantCulture, $"{stopBits} stop bits: S7-200 Freeport always sends one stop bit; use 1"));
            stopBits = null;
        }

        var kind = fields.Word("kind", LinkKind.Cable);
        if (port is null || baud is null || parity is null || dataBits is null || stopBits is null || kind is null)
        {
            return null;
        }

        return new SerialSettings
        {
            PortName = port,
            BaudRate = baud.Value,
            Parity = parity.Value,
            DataBits = dataBits.Value,
            StopBits = stopBits.Value,
            Kind = kind.Value,
        };
    }

    /// <summary>"9600 8N1 cable", as technicians write line settings; "19200 8E1 cable ppi" for a PPI bus.</summary>
    public static string Describe(SerialSettings link) =>
        $"{link.LineText} {JsonWords.Of(link.Kind)}{(link.Protocol == LinkProtocol.Ppi ? " ppi" : "")}";

    /// <summary>The S7-200's PPI rates (seed 002, Tables A-2 to A-4: "PPI/MPI baud rates 9.6, 19.2, and 187.5 kbaud").</summary>
    public static IReadOnlyList<int> PpiRates { get; } = [9600, 19200, 187500];

    private static SerialSettings? ReadPpi(JsonFields fields, string? port)
    {
        var baud = fields.Int("baud", 9600);
        if (baud is { } b && !PpiRates.Contains(b))
        {
            fields.Problem("baud", string.Create(CultureInfo.InvariantCulture, $"PPI runs at {string.Join(", ", PpiRates)} baud, not {b}"));
            baud = null;
        }

        var line = (Parity: fields.Word("parity", Parity.Even), DataBits: fields.Int("dataBits", 8), StopBits: fields.Int("stopBits", 1));
        if (line.Parity is not (null or Parity.Even) || line.DataBits is not (null or 8) || line.StopBits is not (null or 1))
        {
            fields.Problem("parity", "a PPI character is always 8 data bits, even parity, one stop bit (8E1): leave out parity, dataBits and stopBits or give even, 8 and 1");
            return null;
        }

        var kind = fields.Word("kind", LinkKind.Cable);
        if (kind == LinkKind.RadioModule)
        {
            fields.Problem("kind", "the radio modules carry the handler's Freeport frames; a PPI bus needs the cable");
            return null;
        }

        return port is null || baud is null || line.Parity is null || line.DataBits is null || kind is null
            ? null
            : new SerialSettings { PortName = port, BaudRate = baud.Value, Parity = Parity.Even, DataBits = 8, Kind = LinkKind.Cable, Protocol = LinkProtocol.Ppi };
    }
}
