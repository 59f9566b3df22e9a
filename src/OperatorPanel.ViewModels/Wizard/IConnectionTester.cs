using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Link;
using OperatorPanel.Core.Ppi;
using OperatorPanel.Core.Protocol;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// Sends one IDENTIFY for the wizard's "test connection" (docs/protocol-v2.md, "01 IDENTIFY"). The App passes a
/// <see cref="LinkConnectionTester"/> over the serial port (or the demo line); tests pass a fake or the simulated PLC.
/// </summary>
public interface IConnectionTester
{
    /// <summary>
    /// The station's reply (an <see cref="IdentifyResponse"/>, or an <see cref="ErrorResponse"/>), or the link failure
    /// when the port cannot be opened or no valid reply came.
    /// </summary>
    Task<LinkReply> IdentifyAsync(SerialSettings link, Station station, CancellationToken cancellationToken);

    /// <summary>
    /// For a PPI link: what PPI tells about the CPU (SMB6, SM0.7, scan times; docs/ppi.md section 9), or why nothing
    /// came. A tester that cannot speak PPI says so.
    /// </summary>
    Task<PpiIdentifyOutcome> IdentifyPpiAsync(SerialSettings link, Station station, CancellationToken cancellationToken) =>
        Task.FromResult(new PpiIdentifyOutcome(null, "this connection test cannot speak PPI"));
}
