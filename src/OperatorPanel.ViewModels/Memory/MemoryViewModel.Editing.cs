using OperatorPanel.Core.Addressing;
using OperatorPanel.Core.Values;
using OperatorPanel.Core.Writes;
using OperatorPanel.ViewModels.Session;

namespace OperatorPanel.ViewModels.Memory;

/// <summary>Writing a cell's typed value, in the cell's units and inside its range.</summary>
public sealed partial class MemoryViewModel
{
    /// <summary>
    /// Checks the typed text in the cell's units against its type and range (TagValues: RecipeNumber takes 1..8; a REAL
    /// inside the REAL's range), the address for the station's CPU (AddressRules) and the project's write rules
    /// (WriteRules: no byte of a read-only tag, none of the handler's own V bytes), then writes it; a bad value is refused
    /// with a message and nothing goes on the wire. The bus logs the write and puts it on record.
    /// </summary>
    internal async Task CommitAsync(MemoryCellViewModel cell)
    {
        var address = cell.PlcAddress;
        if (!cell.CanEdit)
        {
            Refuse(cell, $"{address}: {(cell.Writable ? "not connected or read-only mode" : "the project marks this cell read-only")}; nothing written");
            return;
        }

        if (!TagValues.TryParse(cell.Tag, cell.EditText, out var bytes, out var valueError))
        {
            Refuse(cell, valueError.Message);
            return;
        }

        if ((LinkAreas.Refusal(address, cell.Station.Link.Protocol, cell.Station.Cpu, AddressUse.Write)
            ?? WriteRules.Refusal(address, cell.Station)) is { } addressError)
        {
            Refuse(cell, addressError);
            return;
        }

        var newValue = TagValues.Format(cell.Tag, bytes.AsSpan());
        var current = cell.HasValue ? cell.ValueText : null;
        if (_options.ConfirmWrites && !await _dialogs.ConfirmAsync("Write memory", WriteMessages.Question(address, cell.Symbol, current, cell.Quality, newValue)))
        {
            return;
        }

        var request = address.Width == AccessWidth.Bit
            ? WriteRequest.Bit(cell.Station.Address, address, bytes[0] != 0)
            : WriteRequest.Bytes(cell.Station.Address, address, bytes);
        cell.EditError = null;
        cell.WriteError = null;
        cell.IsWriting = true;
        WriteOutcome outcome;
        try
        {
            outcome = await _session.WriteAsync(request);
        }
        catch (Exception exception) when (exception is not OutOfMemoryException)
        {
            _logger.Error(exception, "Writing {Address} failed in the panel", address.ToString());
            outcome = new WriteOutcome.Unknown(default, $"the panel failed: {exception.Message}", "it may have reached the PLC");
        }
        finally
        {
            cell.IsWriting = false;
        }

        cell.IsEditing = false;
        cell.WriteError = WriteMessages.Problem(address, cell.Format, outcome);
        var status = WriteMessages.StatusText(cell.Symbol, address, cell.Format, newValue, outcome);
        if (cell.WriteError is null)
        {
            _session.StatusLine.Show(status);
        }
        else
        {
            _session.StatusLine.ShowError(status);
        }
    }

    private void Refuse(MemoryCellViewModel cell, string message)
    {
        cell.EditError = message;
        _session.StatusLine.ShowError(message);
    }
}
